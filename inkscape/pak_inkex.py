"""Imports inkex, Inkscape's Python library, also when a script runs outside Inkscape.

Inkscape puts its own extensions folder on PYTHONPATH before it starts an extension; a script
run by hand (a test, a terminal) has no such path, so the system folder is tried too.
"""
import sys

# Where Linux packages (Debian's `inkscape` among them) install inkex.
SYSTEM_EXTENSION_FOLDERS = ("/usr/share/inkscape/extensions", "/usr/local/share/inkscape/extensions")


def _import_inkex():
    try:
        import inkex  # pylint: disable=import-outside-toplevel
        return inkex
    except ImportError as first_error:
        for folder in SYSTEM_EXTENSION_FOLDERS:
            if folder not in sys.path:
                sys.path.append(folder)
        try:
            import inkex  # pylint: disable=import-outside-toplevel
            return inkex
        except ImportError as error:
            # A missing lxml or numpy shows up here too: name it rather than a traceback.
            sys.stderr.write(
                "Pak extension: cannot import inkex, Inkscape's Python library "
                f"({error or first_error}).\nInstall Inkscape 1.x; on Debian: "
                "apt install inkscape python3-lxml python3-numpy python3-cssselect\n")
            sys.exit(1)


inkex = _import_inkex()
