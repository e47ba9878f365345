"""Decides which objects of the open document are the container and which are the elements.

The rule, in order:
1. Selected objects inside the layer named `container` are the container.
2. Otherwise, if the document has a layer named `container`, that whole layer is.
3. Otherwise the selected object with the largest bounding box is the container.
The other selected objects are the elements, except those in pak's helper layers
(`guides`, `spines`, `fixed`), which pak reads from those layers itself.
Layer names are matched without regard to case, on the label Inkscape shows or on the id,
as pak does.
"""
from pak_copy import root_space_box
from pak_inkex import inkex

HELPER_LAYERS = ("guides", "spines", "fixed")


def layer_names(group):
    """The names a layer goes by: its label in Inkscape and its id (Illustrator's layer name)."""
    return {(group.get(attribute) or "").strip().lower() for attribute in ("inkscape:label", "id")}


def find_layer(svg, name):
    """The first layer (in document order) called name, or None. A layer is an Inkscape layer,
    or a group at the top of the document (how Illustrator writes its layers)."""
    for group in svg.iter("{http://www.w3.org/2000/svg}g"):
        if (isinstance(group, inkex.Layer) or group.getparent() is svg) and name in layer_names(group):
            return group
    return None


def drawn_children(layer):
    """The objects a layer draws (its shapes and groups, not its title or metadata)."""
    return [child for child in layer if isinstance(child, inkex.ShapeElement)]


def _inside(element, layer):
    return layer is not None and (element is layer or layer in element.iterancestors())


def _box_area(element):
    box = root_space_box(element)
    return 0.0 if box is None else box.width * box.height


def split_selection(svg, selected):
    """(container objects, element objects) from the selected objects, in rendering order."""
    container_layer = find_layer(svg, "container")
    helpers = [layer for layer in (find_layer(svg, name) for name in HELPER_LAYERS) if layer is not None]
    in_container = [e for e in selected if _inside(e, container_layer)]
    others = [e for e in selected if not _inside(e, container_layer)]
    if in_container:
        container = in_container
    elif container_layer is not None:
        container = drawn_children(container_layer)
        if not container:
            raise inkex.AbortExtension("Pak: the layer 'container' is empty: draw the closed shape to fill in it.")
    else:
        if not selected:
            raise inkex.AbortExtension(
                "Pak: nothing selected. Select the closed shape to fill together with the objects "
                "to fill it with (or name a layer 'container').")
        largest = max(selected, key=_box_area)
        container = [largest]
        others = [e for e in others if e is not largest]
    elements = [e for e in others if not any(_inside(e, layer) for layer in helpers)]
    return container, elements
