#!/usr/bin/env bash
# The demo of the package.
#
#   bash scripts/demo.sh
#       installs the dependencies, builds the two programs, extracts CGAL's bear mesh and its
#       cone file from Debian's libcgal-demo into build/demo_data, makes an Orbifold Tutte UV map
#       (seamless up to solver error), snaps it, and prints the seam violation before (~1e-13)
#       and after (exactly 0). The result is build/demo_data/bear_exact.obj.
#
#   bash scripts/demo.sh FILE.obj [OUT.obj] [seamless_snap options, e.g. --weld]
#       snaps your own OBJ (triangles, per-corner UVs: f v/vt) with seamless_snap.
#       Default OUT: build/<name of FILE>_exact.obj (in the build directory, so that the input's
#       directory need not be writable). Run build/examples/Seamless_snapping/seamless_snap --help
#       for the options.
#
# Environment: SEAMLESS_SNAPPING_BUILD_DIR (default: <repo>/build), as for scripts/build.sh.
set -euo pipefail

root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
build="${SEAMLESS_SNAPPING_BUILD_DIR:-$root/build}"
bin="$build/examples/Seamless_snapping"

die() { echo "demo: error: $*" >&2; exit 1; }
step() { echo; echo "== $*"; }

case "${1:-}" in
  -h|--help) sed -n '2,16p' "${BASH_SOURCE[0]}" | sed 's/^# \{0,1\}//'; exit 0 ;;
esac

# Check the user's file before the (possibly long) build.
in_file=""; out_file=""; snap_opts=()
while [ $# -gt 0 ]; do
  case "$1" in
    --report) [ $# -ge 2 ] || die "--report needs a file name"
              snap_opts+=("$1" "$2"); shift ;;
    --*) snap_opts+=("$1") ;;
    *) if [ -z "$in_file" ]; then in_file="$1"
       elif [ -z "$out_file" ]; then out_file="$1"
       else die "unexpected argument '$1' (usage: bash scripts/demo.sh [FILE.obj [OUT.obj] [options]])"; fi ;;
  esac
  shift
done
if [ -n "$in_file" ]; then
  [ -f "$in_file" ] || die "input file '$in_file' does not exist"
  [ -r "$in_file" ] || die "input file '$in_file' is not readable"
fi

step "dependencies (scripts/install_deps.sh)"
bash "$root/scripts/install_deps.sh"
echo "ok"

step "build (scripts/build.sh, only the demo programs)"
bash "$root/scripts/build.sh" --target orbifold_to_exact seamless_snap
[ -x "$bin/orbifold_to_exact" ] && [ -x "$bin/seamless_snap" ] || die "the build did not produce $bin/{orbifold_to_exact,seamless_snap}"
echo "ok: $bin"

if [ -n "$in_file" ]; then
  if [ -z "$out_file" ]; then
    name="$(basename "$in_file")"; name="${name%.*}"
    out_file="$build/${name}_exact.obj"
  fi
  step "seamless_snap $in_file -> $out_file ${snap_opts[*]:-}"
  status=0
  "$bin/seamless_snap" "$in_file" "$out_file" "${snap_opts[@]}" || status=$?
  if [ "$status" -ne 0 ]; then
    die "seamless_snap failed (exit $status); no output was written"
  fi
  echo
  echo "demo: done: $out_file is exactly seamless"
  exit 0
fi

step "CGAL data (Debian libcgal-demo) -> $build/demo_data"
data_tar=/usr/share/doc/libcgal-dev/data.tar.gz
examples_tar=/usr/share/doc/libcgal-dev/examples.tar.gz
[ -f "$data_tar" ] || die "$data_tar is missing (it comes with the Debian package libcgal-demo: apt-get install libcgal-demo)"
[ -f "$examples_tar" ] || die "$examples_tar is missing (it comes with the Debian package libcgal-demo: apt-get install libcgal-demo)"
demo="$build/demo_data"
mkdir -p "$demo"
if [ ! -s "$demo/bear.off" ]; then
  tar -xzOf "$data_tar" data/meshes/bear.off > "$demo/bear.off.part" \
    || { rm -f "$demo/bear.off.part"; die "cannot extract data/meshes/bear.off from $data_tar"; }
  mv "$demo/bear.off.part" "$demo/bear.off"
fi
if [ ! -s "$demo/bear.selection.txt" ]; then
  tar -xzOf "$examples_tar" examples/Surface_mesh_parameterization/data/bear.selection.txt > "$demo/bear.selection.txt.part" \
    || { rm -f "$demo/bear.selection.txt.part"; die "cannot extract bear.selection.txt from $examples_tar"; }
  mv "$demo/bear.selection.txt.part" "$demo/bear.selection.txt"
fi
echo "ok: $demo/bear.off, cones (vertex indices) $(head -n1 "$demo/bear.selection.txt")"

step "Orbifold Tutte (Square) on the bear, then exact snapping"
"$bin/orbifold_to_exact" "$demo/bear.off" "$demo/bear.selection.txt" "$demo/bear_exact.obj" \
  || die "orbifold_to_exact failed"

echo
echo "demo: done. Before: CGAL's orbifold map is seamless only up to solver error; after: every seam"
echo "transition holds exactly (checked in rational arithmetic). Result: $demo/bear_exact.obj"
echo "Snap your own file with: bash scripts/demo.sh FILE.obj [OUT.obj] [--weld]"
