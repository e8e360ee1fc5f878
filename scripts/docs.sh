#!/usr/bin/env bash
# Builds the HTML documentation (user manual + reference) with Debian's doxygen, without a CGAL
# source tree: doc/Seamless_snapping/Doxyfile defines the \cgal... commands itself.
#   bash scripts/docs.sh            -> build/doc/html/index.html  (warnings: build/doc/doxygen_warnings.log)
# SEAMLESS_SNAPPING_DOC_DIR overrides the output directory. Not part of the test run.
set -euo pipefail
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
out="${SEAMLESS_SNAPPING_DOC_DIR:-$root/build/doc}"

mathjax=/usr/share/javascript/mathjax                   # Debian's libjs-mathjax: formulas render offline
if ! command -v doxygen >/dev/null 2>&1 || [ ! -f "$mathjax/MathJax.js" ]; then   # idempotent: only when missing
  echo "docs: installing doxygen and libjs-mathjax"
  SUDO=""
  if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $SUDO apt-get update -qq
  $SUDO apt-get install -y -qq --no-install-recommends doxygen libjs-mathjax >/dev/null
fi

mkdir -p "$out"
log="$out/doxygen_warnings.log"
rm -rf "$out/html"
cd "$root"                                              # the Doxyfile's paths are relative to the repository root
{ cat doc/Seamless_snapping/Doxyfile; echo "OUTPUT_DIRECTORY = \"$out\""; echo "WARN_LOGFILE = \"$log\""; } | doxygen - >/dev/null

# MATHJAX_RELPATH = mathjax: a copy of MathJax beside the pages (no network needed to read them)
cp -rL "$mathjax" "$out/html/mathjax"
rm -rf "$out/html/mathjax/unpacked" "$out/html/mathjax/test"   # MathJax's own sources and tests

if [ ! -s "$out/html/index.html" ]; then
  echo "docs: doxygen did not produce $out/html/index.html" >&2
  exit 1
fi
n=$(grep -c . "$log" || true)
echo "docs: $out/html/index.html ($(doxygen --version), $n warning line(s)${n:+, see $log})"
