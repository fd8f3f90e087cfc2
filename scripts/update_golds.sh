#!/usr/bin/env bash
# Regenerates the regression golds (docs/regression.md): for each case (all of regression/*/ with a
# scene.yaml, or the cases named on the command line) runs efg on ONE rank, prints what changed
# against the stored gold (exodiff with the case's command file, and whether the bits changed),
# and copies the result to regression/<case>/gold.e. The mutant gold (regression/mutant_gold) is
# rebuilt from the new timoshenko_scni gold.
#
# Never run in CI: CI compares, it never accepts new results. A gold is only replaced by a
# developer who knows why the results changed and has run the verified test named in the case's
# README.md. The script refuses to run
#   - when `git status --porcelain regression/` is not empty: commit (or drop) the scene and
#     command-file edits first, so that the gold update is the only change left to review;
#   - when CI is set (GitHub Actions, GitLab and most CI systems set it).
# Usage: scripts/update_golds.sh [CASE...]
set -euo pipefail
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$here"

if [ -n "${CI:-}" ]; then
  echo "efg update_golds: refusing to run in CI (CI=$CI): golds are updated by hand and reviewed" >&2
  exit 1
fi
dirty="$(git status --porcelain -- regression/)"
if [ -n "$dirty" ]; then
  echo "efg update_golds: refusing: regression/ has changes that are not committed:" >&2
  echo "$dirty" >&2
  echo "commit (or drop) them first, so that the new golds are the only change to review" >&2
  exit 1
fi

exodiff="$("$here/scripts/build_exodiff.sh")"
"$here/scripts/build.sh"
efg="${EFG_BUILD_DIR:-$here/build}/efg"

cases=("$@")
if [ ${#cases[@]} -eq 0 ]; then
  for scene in regression/*/scene.yaml; do cases+=("$(basename "$(dirname "$scene")")"); done
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

for c in "${cases[@]}"; do
  dir="regression/$c"
  if [ ! -f "$dir/scene.yaml" ] || [ ! -f "$dir/exodiff.cmd" ]; then
    echo "efg update_golds: $dir needs scene.yaml and exodiff.cmd" >&2
    exit 1
  fi
  start=$(date +%s.%N)
  if ! "$efg" run "$dir/scene.yaml" -o "$work/$c" >"$work/$c.log" 2>&1; then
    echo "efg update_golds: efg failed on $c (gold unchanged); end of its log:" >&2
    tail -20 "$work/$c.log" >&2
    exit 1
  fi
  seconds=$(awk "BEGIN { printf \"%.1f\", $(date +%s.%N) - $start }")
  new="$work/$c/scene.e"
  if [ ! -f "$dir/gold.e" ]; then
    echo "$c: new gold (efg ${seconds} s)"
  elif cmp -s "$dir/gold.e" "$new"; then
    echo "$c: unchanged, the same bits (efg ${seconds} s)"
  elif "$exodiff" -f "$dir/exodiff.cmd" "$dir/gold.e" "$new" >"$work/$c.diff" 2>&1; then
    echo "$c: bits changed, but within the tolerances of $dir/exodiff.cmd (efg ${seconds} s)"
  else
    echo "$c: CHANGED beyond the tolerances of $dir/exodiff.cmd (efg ${seconds} s); exodiff (old gold ~ new):"
    { grep -E "DIFFERENCE|diff:|exodiff: Files" "$work/$c.diff" || true; } | head -40 | sed 's/^/    /'
  fi
  cp "$new" "$dir/gold.e"
  if [ "$c" = timoshenko_scni ]; then
    /usr/bin/python3 regression/mutant_gold/make_gold.py "$dir/gold.e" regression/mutant_gold/gold.e | sed 's/^/    /'
  fi
done

echo "Golds written. Before committing them: check that each changed case is right (its README.md names"
echo "the verified test to run), then run the suite on 1 and 2 ranks: (cd build && ctest -L regression)."
git status --short -- regression/
