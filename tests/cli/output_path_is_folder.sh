#!/usr/bin/env bash
# A results (or history) path that names an existing folder is bad input found before the run:
# exit 2 on every rank count (issue 14, item 2: on 2 ranks it hung after the stage), the message
# names the key, and nothing in the output folder changes.
#   output_path_is_folder.sh "LAUNCHER" EFG SCENE OUTDIR FOLDER_NAME
set -u
launcher="$1" efg="$2" scene="$3" out="$4" name="$5"
rm -rf "$out" && mkdir -p "$out/$name"
echo "kept" > "$out/$name/inside"
# shellcheck disable=SC2086
log="$(timeout 100 $launcher "$efg" run "$scene" -o "$out" 2>&1)"
code=$?
fail() { echo "FAILED: $*"; echo "$log"; exit 1; }
[ $code -eq 2 ] || fail "exit code $code, expected 2"
echo "$log" | grep -q "is an existing folder; expected a file name for the results" || fail "no message"
[ "$(ls -A "$out")" = "$name" ] || fail "the output folder changed: $(ls -A "$out")"
[ "$(ls -A "$out/$name")" = "inside" ] && [ "$(cat "$out/$name/inside")" = "kept" ] || fail "the folder's content changed"
log="$("$efg" check "$scene" -o "$out" 2>&1)"
[ $? -eq 2 ] || fail "efg check did not find it"
echo "refused with exit 2, nothing touched"
