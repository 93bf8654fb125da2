#!/usr/bin/env bash
# The Snakemake pipeline on the local executor: outputs equal the direct tool chain byte for byte;
# a second run does nothing; a changed card reruns only its own scene.
# Usage: pipeline_test.sh SOURCE_DIR BIN_DIR. Exit 77 (skipped) without snakemake.
set -euo pipefail
SRC=$1 BIN=$2
if ! command -v snakemake >/dev/null; then
  echo "SKIP: snakemake is not installed (scripts/setup installs it)"
  exit 77
fi
WORK=$(mktemp -d "${TMPDIR:-/tmp}/kdpm-pipeline.XXXXXX")
trap 'rm -rf "$WORK"' EXIT
source "$SRC/tests/pipeline/pipeline_lib.sh"

make_library
write_config "$WORK/config.yaml" "$WORK/out"
run() { snakemake -s "$SRC/pipeline/Snakefile" --configfile "$WORK/config.yaml" --directory "$WORK" --cores all \
          --rerun-triggers mtime params input code "$@" > "$WORK/snakemake.log" 2>&1 \
          || { tail -n 40 "$WORK/snakemake.log"; echo "FAIL: snakemake $*"; exit 1; }; }

run
direct_chain "$WORK/scenes/a/cornell-box.json" "$WORK/direct"
(cd "$WORK/direct" && for f in scene.kdg scene.kdph scene.kdp; do "$BIN/kdpm-validate" $f; done > validated.txt)
for name in a b; do
  same_files "$WORK/out/$name" "$WORK/direct" $OUTPUTS
done
[ "$(ls "$WORK/out/a/shards" | wc -l)" -eq "$SHARDS" ] || { echo "FAIL: expected $SHARDS shards"; exit 1; }
echo "pipeline outputs equal the direct tool chain"

# Nothing changed: nothing runs, nothing is rewritten.
touch "$WORK/marker"
sleep 1
touch "$WORK/scenes/a/cornell-box.json"  # a newer card with the same bytes is not a change
run
grep -q "Nothing to be done" "$WORK/snakemake.log" || { cat "$WORK/snakemake.log"; echo "FAIL: the second run did work"; exit 1; }
[ -z "$(find "$WORK/out" -newer "$WORK/marker" -type f)" ] || { echo "FAIL: the second run rewrote files"; exit 1; }
echo "a second run does nothing"

# Scene b's card changes (another k): b's jobs rerun, a's outputs stay as they were.
sed -i 's/"k": 64/"k": 32/' "$WORK/scenes/b/cornell-box.json"
run
changed=$(cd "$WORK/out" && find . -newer "$WORK/marker" -type f | sort | tr '\n' ' ')
expected="./b/preview.png ./b/scene.kdg ./b/scene.kdp ./b/scene.kdph ./b/shards/part-0-of-4.kdph ./b/shards/part-1-of-4.kdph ./b/shards/part-2-of-4.kdph ./b/shards/part-3-of-4.kdph ./b/validated.txt "
[ "$changed" = "$expected" ] || { echo "FAIL: after changing b's card, rewritten: $changed"; exit 1; }
direct_chain "$WORK/scenes/b/cornell-box.json" "$WORK/direct-b"
same_files "$WORK/out/b" "$WORK/direct-b" scene.kdg scene.kdph scene.kdp preview.png
echo "a changed card reruns only its scene"
