#!/usr/bin/env bash
# `cmake --install BUILD --prefix P` (what `make install PREFIX=P` runs) puts a working pak in
# P/bin, a man page per command in P/share/man/man1 and bash completion that completes
# commands and options. Usage: install_test.sh BUILD_DIR
set -euo pipefail
build=$1
prefix=$(mktemp -d)
trap 'rm -rf "$prefix"' EXIT
cmake --install "$build" --prefix "$prefix" > /dev/null
fail() { echo "install_test: $*" >&2; exit 1; }
[ -x "$prefix/bin/pak" ] || fail "no bin/pak"
version=$("$prefix/bin/pak" --version) || fail "pak --version failed"
[[ $version == "pak "* ]] || fail "pak --version said '$version'"
for page in pak pak-pack pak-flow pak-animate pak-metrics pak-inspect pak-render; do
  file="$prefix/share/man/man1/$page.1"
  [ -s "$file" ] || fail "no man page $page.1"
  title=$(echo "$page" | tr '[:lower:]' '[:upper:]')
  grep -q "^\.TH $title " "$file" || fail "$page.1 is not titled $title"
done
grep -q 'mirror' "$prefix/share/man/man1/pak-flow.1" || fail "pak-flow.1 lacks the options"
completion="$prefix/share/bash-completion/completions/pak"
[ -s "$completion" ] || fail "no bash completion"
words=$(bash -c "source '$completion'; COMP_WORDS=('$prefix/bin/pak' fl); COMP_CWORD=1; _pak; echo \${COMPREPLY[*]}")
[ "$words" = flow ] || fail "completing 'pak fl' gave '$words'"
words=$(bash -c "source '$completion'; COMP_WORDS=('$prefix/bin/pak' flow --mirr); COMP_CWORD=2; _pak; echo \${COMPREPLY[*]}")
[ "$words" = --mirror ] || fail "completing 'pak flow --mirr' gave '$words'"
echo "install_test: pak, 7 man pages and completion under $prefix"
