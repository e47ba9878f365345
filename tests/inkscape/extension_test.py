"""Runs the Inkscape extension's scripts (inkscape/pak_pack.py, pak_flow.py) as Inkscape runs
them: `python3 pak_pack.py --id=... --option=... document.svg > result.svg`. On the test
documents of this folder it checks that
- the result is one new layer, on top, holding the packed elements (counted);
- the packing lies over the container, in the document's user units, through the viewBox
  scale and the transforms of the container and its layer (bounding boxes);
- the elements keep their colours, and every id in the document stays unique;
- nothing else in the document changed (the document without the new layer is the input,
  node for node);
- bad input and a missing or failing pak give one clear message, never a traceback.
pak runs with few elements and iterations so the whole test takes seconds.
Usage: extension_test.py PAK SOURCE_DIR (extension_test.sh finds a python3 with inkex).
"""
import os
import re
import subprocess
import sys
import tempfile

import inkex
from lxml import etree

PAK, SOURCE = sys.argv[1], sys.argv[2]
EXTENSION = os.path.join(SOURCE, "inkscape")
HERE = os.path.join(SOURCE, "tests", "inkscape")
SVG = "{http://www.w3.org/2000/svg}"
LABEL = "{http://www.inkscape.org/namespaces/inkscape}label"
failures = []


def check(condition, what):
    print(("ok   " if condition else "FAIL ") + what)
    if not condition:
        failures.append(what)
    return condition


def run(script, document, *options, env=None):
    """Runs an extension script; returns (exit code, stdout bytes, stderr text)."""
    environment = dict(os.environ, PAK=PAK)
    environment.update(env or {})
    done = subprocess.run([sys.executable, os.path.join(EXTENSION, script), *options, document],
                          capture_output=True, env=environment, timeout=300)
    return done.returncode, done.stdout, done.stderr.decode(errors="replace")


def first_difference(a, b, path="/"):
    """Where two trees differ first (tag, attributes, text, children), or None."""
    where = path + str(a.tag)
    if a.tag != b.tag or dict(a.attrib) != dict(b.attrib):
        return f"{where}: {a.tag} {dict(a.attrib)} became {b.tag} {dict(b.attrib)}"
    if (a.text or "").strip() != (b.text or "").strip():
        return f"{where}: text {a.text!r} became {b.text!r}"
    if len(a) != len(b):
        return f"{where}: {len(a)} children became {len(b)}"
    for child_a, child_b in zip(a, b):
        difference = first_difference(child_a, child_b, where + "/")
        if difference:
            return difference
    return None


def new_layer_and_rest(before_path, after_bytes):
    """The output's one new layer, and whether the rest is the input unchanged (else why)."""
    before = etree.parse(before_path).getroot()
    after = etree.fromstring(after_bytes)
    added = list(after)[len(before):]
    if len(added) != 1 or len(after) != len(before) + 1:
        return None, f"{len(after) - len(before)} new top-level nodes instead of 1"
    layer = added[0]
    after.remove(layer)
    same = etree.tostring(before, method="c14n") == etree.tostring(after, method="c14n")
    return layer, (None if same else first_difference(before, after) or "the canonical XML differs")


def element_count(layer):
    return sum(1 for child in layer if child.tag == SVG + "g" and "element" in (child.get("class") or "").split())


def boxes(after_bytes, container_ids, layer_label):
    """(container box, result layer box) in root user units, from the output document."""
    svg = inkex.load_svg(after_bytes).getroot()
    container = None
    for element_id in container_ids:
        element = svg.getElementById(element_id)
        box = element.bounding_box(element.getparent().composed_transform())
        container = box if container is None else container + box
    layer = next(g for g in svg.iter(SVG + "g") if g.get(LABEL) == layer_label)
    return container, layer.bounding_box()


def check_placement(container, result, name):
    """The packing lies inside the container's box (a little stroke and outline slack) and
    spreads over most of it: it fills the container, not somewhere else or at another scale."""
    slack = 0.03 * max(container.width, container.height)
    inside = (result.left >= container.left - slack and result.right <= container.right + slack
              and result.top >= container.top - slack and result.bottom <= container.bottom + slack)
    check(inside, f"{name}: the packing {result} lies within the container {container}")
    check(result.width >= 0.5 * container.width and result.height >= 0.5 * container.height,
          f"{name}: the packing spreads over the container (at least half its width and height)")


def check_run(name, script, document, options, layer_label, count, container_ids, colours):
    code, out, err = run(script, document, *options)
    if not check(code == 0, f"{name}: the extension exits 0 (exit {code}; stderr: {err.strip()[-400:]})"):
        return None
    check("Traceback" not in err, f"{name}: no traceback on stderr")
    layer, difference = new_layer_and_rest(document, out)
    if not check(layer is not None, f"{name}: one new top-level node ({difference})"):
        return None
    check(difference is None, f"{name}: the rest of the document is unchanged ({difference})")
    check(layer.tag == SVG + "g" and layer.get("{http://www.inkscape.org/namespaces/inkscape}groupmode") == "layer"
          and layer.get(LABEL) == layer_label, f"{name}: it is a layer labelled '{layer_label}'")
    check(layer.get("transform") is None, f"{name}: the layer has no transform (document user units)")
    found = element_count(layer)
    check(count(found), f"{name}: element count {found}")
    check(found == len(layer), f"{name}: the layer holds only elements ({len(layer)} children)")
    ids = etree.fromstring(out).xpath("//@id")
    check(len(ids) == len(set(ids)), f"{name}: ids unique in the document")
    painted = set(c.lower() for c in re.findall(r"#[0-9a-fA-F]{6}", etree.tostring(layer).decode()))
    check(set(colours) <= painted, f"{name}: the elements keep their colours {colours} (found {sorted(painted)})")
    check_placement(*boxes(out, container_ids, layer_label), name)
    return out


def check_error(name, script, document, options, expected, env=None):
    code, out, err = run(script, document, *options, env=env)
    check(code != 0, f"{name}: fails (exit {code})")
    check("Traceback" not in err and expected in err, f"{name}: says '{expected}' without a traceback ({err.strip()!r})")
    check(not out.strip(), f"{name}: writes no document")


pack_document = os.path.join(HERE, "pack-document.svg")
flow_document = os.path.join(HERE, "flow-document.svg")
fast_pack = ["--count=6", "--max_iterations=300", "--seed=3", "--time_limit=0"]

# The container chosen as the largest selected object, moved by its layer and its own
# transform, on a page whose viewBox is twice its size in mm; the gap given in mm.
check_run("pack selection", "pak_pack.py", pack_document,
          ["--id=dot", "--id=blob", "--id=drop", "--id=flower", "--gap=1mm", *fast_pack],
          "Pak pack", lambda n: n == 6, ["blob"], ["#e63946", "#1d6fa5", "#2a9d5c", "#f2c14e"])
# The container from the layer named `container`; the elements from a folder.
check_run("pack folder", "pak_pack.py", flow_document,
          ["--elements_source=folder", f"--folder={os.path.join(SOURCE, 'examples', 'elements')}",
           "--layer_name=Packed", *fast_pack],
          "Packed", lambda n: n == 6, ["lens"], [])
# Flow along the `guides` layer (moved by its own transform), the selected leaves bent along it.
check_run("flow selection", "pak_flow.py", flow_document,
          ["--id=leaf-green", "--id=leaf-orange", "--count=12", "--iterations=1", "--time_limit=0"],
          "Pak flow", lambda n: 4 <= n <= 60, ["lens"], ["#3a7d44", "#e07a2f"])

check_error("pak missing", "pak_pack.py", pack_document, ["--id=blob", "--id=dot", "--pak=/nonexistent/pak"],
            "not a program")
check_error("pak fails", "pak_pack.py", pack_document, ["--id=blob", "--id=dot", "--gap=2 parsecs", *fast_pack],
            "pak: error:")
check_error("nothing selected", "pak_pack.py", pack_document, [], "nothing selected")
check_error("only the container", "pak_pack.py", pack_document, ["--id=blob"], "nothing to pack")
check_error("no folder", "pak_pack.py", pack_document,
            ["--id=blob", "--elements_source=folder", "--folder=/nonexistent/folder"], "does not exist")
check_error("flow without guides", "pak_flow.py", pack_document, ["--id=blob", "--id=dot"], "'guides'")
with tempfile.NamedTemporaryFile("w", suffix=".svg") as broken:
    broken.write("this is not SVG")
    broken.flush()
    check_error("not SVG", "pak_pack.py", broken.name, ["--id=a"], "cannot read the document")
# No pak anywhere: only where the fallback places hold none either (a machine with pak
# installed in /usr/local/bin would find it there, rightly).
if not any(os.access(p, os.X_OK) for p in ("/usr/local/bin/pak", os.path.expanduser("~/.local/bin/pak"))):
    check_error("pak not on the PATH", "pak_pack.py", pack_document, ["--id=blob", "--id=dot"],
                "was not found on the PATH", env={"PAK": "", "PATH": "/nonexistent"})

print(f"extension_test: {len(failures)} failure(s)" if failures else "extension_test: all passed")
sys.exit(1 if failures else 0)
