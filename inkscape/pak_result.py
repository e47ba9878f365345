"""Brings pak's packing back into the open document as a new layer on top.

pak writes its output in the scene's user units, which are the document's (the scene copies
its width, height and viewBox), so the packed elements go in as they are, untransformed.
"""
from pak_inkex import inkex

SVG_G = "{http://www.w3.org/2000/svg}g"


def _unique_label(svg, wanted):
    taken = {g.get("inkscape:label") for g in svg.iter(SVG_G) if isinstance(g, inkex.Layer)}
    label, number = wanted, 2
    while label in taken:
        label, number = f"{wanted} {number}", number + 1
    return label


def _give_unique_ids(svg, subtree, prefix):
    """pak copies the elements' ids into every copy it places: renumber them so that the
    document's ids stay unique (Inkscape relies on it)."""
    taken = set(svg.xpath("//@id"))
    number = 1
    for node in subtree.iter():
        if node.get("id") is None and node is not subtree:
            continue
        while f"{prefix}{number}" in taken:
            number += 1
        node.set("id", f"{prefix}{number}")
        taken.add(f"{prefix}{number}")


def add_result_layer(svg, output_path, label):
    """Adds the `elements` layer of pak's output file to svg as a new layer; returns it."""
    try:
        output = inkex.load_svg(output_path).getroot()
    except Exception as error:  # pylint: disable=broad-except
        raise inkex.AbortExtension(f"Pak: its output could not be read back ({error}).") from None
    packed = next((g for g in output.iter(SVG_G) if (g.get("id") or "").lower() == "elements"), None)
    if packed is None or len(packed) == 0:
        raise inkex.AbortExtension("Pak: the run gave no elements (its output has no 'elements' layer).")
    layer = inkex.Layer.new(_unique_label(svg, label))
    for child in list(packed):
        layer.append(child)
    svg.append(layer)
    _give_unique_ids(svg, layer, "pak-")
    return layer
