#!/usr/bin/env bash
# The outputs of two seamless_snap programs compared file for file: every OBJ under the given inputs
# (default ../shared/data), snapped by both in each mode, the output OBJ files compared byte for byte
# (cmp) and the exit statuses compared. Files under a "directional" folder get --weld (cut meshes).
#
#   benchmark/compare_cli_outputs.sh OLD_SEAMLESS_SNAP NEW_SEAMLESS_SNAP [--mode "ARGS"]... [FILE.obj | DIR]...
#
# Modes default to "" (plain), "--integer-grid" and "--integer-grid --no-untangle"; a mode whose flags the old
# program does not know is given to it without them (e.g. --no-untangle before issue 24, where the
# integer-grid snap did not untangle), and the line says so. Prints one line per file and mode, then a
# summary; exit status 1 if any output differs.
set -uo pipefail
old="$1"; new="$2"; shift 2
modes=(); inputs=()
while [ $# -gt 0 ]; do
  if [ "$1" = "--mode" ]; then modes+=("$2"); shift 2; else inputs+=("$1"); shift; fi
done
[ ${#modes[@]} -eq 0 ] && modes=("" "--integer-grid" "--integer-grid --no-untangle")
root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
[ ${#inputs[@]} -eq 0 ] && inputs=("$root/../shared/data")
tmp="$(mktemp -d)"; trap 'rm -rf "$tmp"' EXIT
mapfile -t files < <(for i in "${inputs[@]}"; do if [ -d "$i" ]; then find "$i" -name '*.obj'; else echo "$i"; fi; done | sort)
old_help="$("$old" --help 2>&1)"
knows() { case "$old_help" in *"$1"*) return 0;; *) return 1;; esac; }   # does the old program know flag $1
same=0; differ=0
for mode in "${modes[@]}"; do
  old_mode=""; dropped=""
  for flag in $mode; do
    if knows "$flag"; then old_mode="$old_mode $flag"; else dropped="$dropped $flag"; fi
  done
  for f in "${files[@]}"; do
    weld=""; case "$f" in */directional/*) weld="--weld";; esac
    n="$(basename "$f" .obj)"
    "$old" "$f" "$tmp/old.obj" $weld $old_mode --quiet 2>"$tmp/old.err"; a=$?
    "$new" "$f" "$tmp/new.obj" $weld $mode --quiet 2>"$tmp/new.err"; b=$?
    if [ $a = $b ] && { [ $a != 0 ] || cmp -s "$tmp/old.obj" "$tmp/new.obj"; }; then
      r="same"; same=$((same + 1))
    else
      r="DIFFERENT"; differ=$((differ + 1))
    fi
    printf '%-36s %-30s exit %s/%s  %s%s\n' "$n" "[${mode:-plain}]" "$a" "$b" "$r" "${dropped:+  (old without$dropped)}"
    rm -f "$tmp/old.obj" "$tmp/new.obj"
  done
done
echo "compare_cli_outputs: $same same, $differ different (byte-identical OBJ files and equal exit statuses)"
[ $differ = 0 ]
