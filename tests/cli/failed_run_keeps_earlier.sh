#!/usr/bin/env bash
# A failed run (exit 3) leaves an earlier result and history of the same name untouched and its
# own records in <name>.part files that the message names (issue 14, item 6 and 7).
#   failed_run_keeps_earlier.sh EFG SCENE OUTDIR NAME
set -u
efg="$1" scene="$2" out="$3" name="$4"
rm -rf "$out" && mkdir -p "$out"
echo "earlier result" > "$out/$name.e"
log="$("$efg" run "$scene" -o "$out" 2>&1)"
code=$?
fail() { echo "FAILED: $*"; echo "$log"; exit 1; }
[ $code -eq 3 ] || fail "exit code $code, expected 3"
[ "$(cat "$out/$name.e")" = "earlier result" ] || fail "the earlier $name.e was replaced"
[ -s "$out/$name.e.part" ] || fail "no $name.e.part with the records up to the failure"
echo "$log" | grep -q "results up to the failure: $out/$name.e.part" || fail "the message does not name the .part file"
echo "earlier result kept, partial result in $out/$name.e.part"
