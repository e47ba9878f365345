"""Finds the `pak` program and runs it, turning its failures into messages for the user."""
import os
import shutil
import signal
import subprocess

from pak_inkex import inkex

# Desktop sessions often start Inkscape without ~/.local/bin on the PATH, where
# `make install PREFIX=~/.local` puts pak; /usr/local/bin is `make install`'s default.
FALLBACK_LOCATIONS = ("~/.local/bin/pak", "/usr/local/bin/pak")

NOT_FOUND_HELP = (
    "Install Pak (`make install` in its source folder) and put `pak` on the PATH, "
    "or give its full path in the dialogue's Advanced tab or in the PAK environment variable.")


def _runnable(path):
    return os.path.isfile(path) and os.access(path, os.X_OK)


def find_pak(option_value):
    """The pak executable: the dialogue's option, else $PAK, else the PATH, else the usual places."""
    for origin, given in (("the 'pak program' option", option_value), ("PAK", os.environ.get("PAK", ""))):
        given = given.strip()
        if given:
            path = shutil.which(os.path.expanduser(given))
            if path is None:
                raise inkex.AbortExtension(f"Pak: {origin} says '{given}', which is not a program. {NOT_FOUND_HELP}")
            return path
    path = shutil.which("pak")
    if path:
        return path
    for candidate in FALLBACK_LOCATIONS:
        candidate = os.path.expanduser(candidate)
        if _runnable(candidate):
            return candidate
    raise inkex.AbortExtension(f"Pak: the program `pak` was not found on the PATH. {NOT_FOUND_HELP}")


def run_pak(pak, arguments, hide_prefix=""):
    """Runs pak; returns its warnings. Raises AbortExtension with pak's own message on failure.

    hide_prefix (the temporary folder) is cut from messages: they name the user's objects
    by the file names the extension gave them, not by a path that is gone after the run.
    """
    try:
        process = subprocess.Popen([pak] + arguments, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                                   stderr=subprocess.PIPE, text=True, errors="replace")
    except OSError as error:
        raise inkex.AbortExtension(f"Pak: cannot run '{pak}': {error.strerror}. {NOT_FOUND_HELP}") from None

    # Inkscape's Cancel button terminates this script: stop pak too rather than leave it running.
    def stop(_signum, _frame):
        process.kill()
        process.wait()
        process.stdout.close()
        process.stderr.close()
        raise inkex.AbortExtension("Pak: cancelled.")
    previous = {s: signal.signal(s, stop) for s in (signal.SIGTERM, signal.SIGINT)}
    try:
        _, stderr = process.communicate()
    finally:
        for s, handler in previous.items():
            signal.signal(s, handler)

    lines = [line.replace(hide_prefix, "") if hide_prefix else line for line in stderr.splitlines()]
    if process.returncode == 0:
        return [line for line in lines if line.startswith("pak: warning:")]
    errors = [line for line in lines if line.startswith("pak: error:")]
    if errors:
        raise inkex.AbortExtension("Pak stopped with an error:\n" + "\n".join(errors))
    if process.returncode < 0:
        what = f"was killed by signal {-process.returncode}"
    else:
        what = f"failed with exit code {process.returncode}"
    tail = "\n".join(lines[-5:])
    raise inkex.AbortExtension(f"Pak: `{os.path.basename(pak)}` {what}." + (f"\nIts last messages:\n{tail}" if tail else ""))
