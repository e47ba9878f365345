#!/usr/bin/env bash
# Runs the Inkscape extension's scripts as Inkscape does, on the test documents here, with
# Debian's inkex (extension_test.py says what it checks). Exits 77, which CTest reports as
# skipped, when no python3 here can import inkex. Usage: extension_test.sh PAK SOURCE_DIR
set -euo pipefail
pak=$1 source=$2
# Inkscape starts extensions with its extensions folder on PYTHONPATH; so does this test.
export PYTHONPATH=/usr/share/inkscape/extensions${PYTHONPATH:+:$PYTHONPATH}
# The first python3 on the PATH may be a private one (pyenv) without lxml; Debian's inkex is
# for Debian's python3.
for python in python3 /usr/bin/python3; do
  if "$python" -c 'import inkex' 2> /dev/null; then
    exec "$python" "$source/tests/inkscape/extension_test.py" "$pak" "$source"
  fi
done
echo "extension_test: skipped: no python3 can import inkex (Debian: inkscape python3-lxml" \
  "python3-numpy python3-cssselect, which scripts/install-deps.sh installs)"
exit 77
