"""Copies an object of the open document so that it looks the same in a file of its own.

pak reads each file on its own, so a copy must carry what the object gets from its ancestors:
their transforms (a layer moved on the page, a scaled group) and the paint it inherits from
them (a layer's fill or stroke), while the file keeps the document's user units.
"""
import copy

from inkex.properties import all_properties

from pak_inkex import inkex

INHERITED = 3  # index of the "inherited" flag in inkex's property table


def inherited_style(element):
    """The style element gets from its ancestors, as one Style: the inheritable properties, and
    their opacities multiplied (opacity is not inherited, yet a half-transparent layer shows
    everything in it half-transparent)."""
    parent = element.getparent()
    if not isinstance(parent, inkex.BaseElement):
        return inkex.Style()
    specified = parent.specified_style()
    style = inkex.Style([(key, value) for key, value in specified.items()
                         if key in all_properties and all_properties[key][INHERITED]])
    opacity = 1.0
    for ancestor in element.iterancestors():
        if isinstance(ancestor, inkex.BaseElement):
            opacity *= _opacity(ancestor)
    if opacity < 1.0:
        style["opacity"] = f"{opacity:.4g}"
    return style


def _opacity(element):
    value = element.style.get("opacity", element.get("opacity", "1"))
    try:
        return min(max(float(str(value).strip().rstrip("%")) / (100.0 if "%" in str(value) else 1.0), 0.0), 1.0)
    except ValueError:
        return 1.0


def root_space_copy(element):
    """A deep copy of element wrapped in a group that gives it its ancestors' transform and paint.

    Placed at the root of an SVG with the document's viewBox, it lies where the original lies.
    """
    wrapper = inkex.Group()
    parent = element.getparent()
    if isinstance(parent, inkex.BaseElement):
        transform = parent.composed_transform()
        if transform != inkex.Transform():
            wrapper.transform = transform
    style = inherited_style(element)
    if style:
        wrapper.style = style
    wrapper.append(copy.deepcopy(element))
    return wrapper


def root_space_box(element):
    """The bounding box of element in the document's user units (None if it draws nothing)."""
    parent = element.getparent()
    transform = parent.composed_transform() if isinstance(parent, inkex.BaseElement) else inkex.Transform()
    return element.bounding_box(transform)
