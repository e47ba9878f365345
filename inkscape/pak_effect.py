"""What Pack and Flow share: the dialogue's common options and the run itself.

A run writes the container (and helper layers) and the elements to a temporary folder, runs
pak on them, and adds pak's packing to the open document as a new layer. Nothing else in
the document changes; if anything fails the document is left as it was.
"""
import os
import shlex
import tempfile

from lxml import etree

from pak_inkex import inkex
from pak_program import find_pak, run_pak
from pak_result import add_result_layer
from pak_roles import find_layer, drawn_children, split_selection
from pak_scene import write_elements, write_scene


class PakEffect(inkex.EffectExtension):
    """Base of the Pack and Flow extensions; subclasses set the class attributes and
    add_pak_arguments / pak_arguments."""

    command = ""            # pak's subcommand
    result_label = ""       # the new layer's default name
    helper_layers = ()      # layers copied into the scene as they are, when the document has them
    required_layers = {}    # layer name: message when the document lacks it

    def add_arguments(self, pars):
        pars.add_argument("--tab", default="")  # the notebook page shown; not an option
        pars.add_argument("--elements_source", default="selection", choices=("selection", "folder"))
        pars.add_argument("--folder", default="")
        pars.add_argument("--gap", default="")
        pars.add_argument("--seed", type=int, default=1)
        pars.add_argument("--time_limit", type=float, default=60.0)
        pars.add_argument("--curves", type=inkex.Boolean, default=True)
        pars.add_argument("--layer_name", default=self.result_label)
        pars.add_argument("--pak", default="")
        pars.add_argument("--extra", default="")
        self.add_pak_arguments(pars)

    def add_pak_arguments(self, pars):
        """The subcommand's own options."""

    def pak_arguments(self):
        """The subcommand's own options as pak arguments."""
        return []

    def load_raw(self):
        # A file that is not SVG gets a sentence, not lxml's traceback.
        try:
            super().load_raw()
        except (OSError, ValueError, AttributeError, etree.XMLSyntaxError) as error:
            # inkex fails with an AttributeError on a file without any XML element.
            raise inkex.AbortExtension(f"Pak: cannot read the document as SVG ({error}).") from None

    def effect(self):
        # Whatever goes wrong, the user reads a sentence, not a traceback.
        try:
            self._run()
        except inkex.AbortExtension:
            raise
        except Exception as error:  # pylint: disable=broad-except
            raise inkex.AbortExtension(
                f"Pak extension: unexpected {type(error).__name__}: {error}. Please report it.") from None

    def _run(self):
        pak = find_pak(self.options.pak)
        # Read from a copy: inkex rewrites an attribute such as transform as soon as it is read
        # (`translate(20,-6)` becomes `translate(20, -6)`), and the document must not change.
        source = inkex.load_svg(etree.tostring(self.document)).getroot()
        source.selection.set(*self.options.ids)
        selected = list(source.selection.rendering_order().values())
        for name, message in self.required_layers.items():
            layer = find_layer(source, name)
            if layer is None or not drawn_children(layer):
                raise inkex.AbortExtension(message)
        container, elements = split_selection(source, selected)
        if self.options.elements_source == "selection" and not elements:
            raise inkex.AbortExtension(
                "Pak: nothing to pack. Select the objects to pack together with the container "
                "(Shift+click), or choose 'Fill with: the SVG files of a folder' in the dialogue.")
        folder = self._checked_folder()

        with tempfile.TemporaryDirectory(prefix="pak-inkscape-") as work:
            scene = os.path.join(work, "scene.svg")
            layers = {"container": container}
            for name in self.helper_layers:
                layer = find_layer(source, name)
                if layer is not None:
                    layers[name] = drawn_children(layer)
            write_scene(source, layers, scene)
            if folder is None:
                folder = os.path.join(work, "elements")
                os.mkdir(folder)
                write_elements(source, elements, folder)
            output = os.path.join(work, "packing.svg")
            arguments = [self.command, "--container", scene, "--elements", folder, "--output", output]
            arguments += self._common_arguments() + self.pak_arguments() + self._extra_arguments()
            warnings = run_pak(pak, arguments, hide_prefix=work + os.sep)
            add_result_layer(self.svg, output, self.options.layer_name.strip() or self.result_label)
        if warnings:
            self.msg("\n".join(warnings))

    def _checked_folder(self):
        if self.options.elements_source != "folder":
            return None
        folder = os.path.expanduser(self.options.folder.strip())
        if not folder:
            raise inkex.AbortExtension("Pak: choose the folder of element SVG files in the dialogue.")
        if not os.path.isdir(folder):
            raise inkex.AbortExtension(f"Pak: the elements folder '{folder}' does not exist.")
        return folder

    def _common_arguments(self):
        arguments = ["--seed", str(self.options.seed)]
        if self.options.gap.strip():
            arguments += ["--gap", self.options.gap.strip()]
        if self.options.time_limit > 0:
            arguments += ["--time-limit", f"{self.options.time_limit:g}"]
        if not self.options.curves:
            arguments.append("--polyline")
        return arguments

    def _extra_arguments(self):
        try:
            return shlex.split(self.options.extra)
        except ValueError as error:
            raise inkex.AbortExtension(f"Pak: the extra options '{self.options.extra}' cannot be read: {error}.") from None
