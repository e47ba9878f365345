"""Writes the files pak reads: the scene (one layer per role) and one file per element.

Every file keeps the document's width, height and viewBox, so pak's output comes back in the
document's user units, and lengths such as `2mm` mean what they mean in Inkscape.
"""
import copy
import re

from pak_copy import root_space_copy
from pak_inkex import inkex

SIZE_ATTRIBUTES = ("width", "height", "viewBox")


def new_document_like(svg):
    """An empty SVG document with svg's size attributes and a copy of its <defs>."""
    document = inkex.load_svg(
        b'<svg xmlns="http://www.w3.org/2000/svg" '
        b'xmlns:inkscape="http://www.inkscape.org/namespaces/inkscape"/>').getroot()
    for name in SIZE_ATTRIBUTES:
        if svg.get(name) is not None:
            document.set(name, svg.get(name))
    # Gradients and the like that the shapes refer to live there.
    for defs in svg.findall("{http://www.w3.org/2000/svg}defs"):
        document.append(copy.deepcopy(defs))
    return document


def _write(document, path):
    document.getroottree().write(path, encoding="utf-8", xml_declaration=True)


def write_scene(svg, layers, path):
    """Writes layers ({name: [objects]}) as a scene file for pak at path."""
    document = new_document_like(svg)
    for name, objects in layers.items():
        layer = inkex.Layer.new(name)
        layer.set("id", name)
        for element in objects:
            layer.append(root_space_copy(element))
        document.append(layer)
    _write(document, path)


def write_elements(svg, objects, folder):
    """Writes each object as an element file in folder; names them NNN-ID.svg, in order."""
    for number, element in enumerate(objects, 1):
        document = new_document_like(svg)
        # One top-level group per file: pak reads the file as one element.
        document.append(root_space_copy(element))
        name = re.sub(r"[^A-Za-z0-9_.-]", "_", element.get("id") or "object")
        _write(document, f"{folder}/{number:03d}-{name}.svg")
