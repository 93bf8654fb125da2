# Shared by the pipeline tests (sourced): a small library of scene copies, its snakemake config,
# the same scenes through the tools directly, and byte-for-byte comparison of the two.
# Needs: SRC (repository), BIN (built tools), WORK (an empty temporary folder).

PHOTONS=20000 SHARDS=4 BOUNCES=4 SEED=3

# Scenes a and b: two copies of the Cornell box, so a change to one card shows what reruns.
make_library() {
  local name
  for name in a b; do
    mkdir -p "$WORK/scenes/$name"
    cp "$SRC"/scenes/cornell-box/cornell-box.{json,obj,mtl} "$WORK/scenes/$name/"
  done
}

# write_config FILE OUT [extra scene YAML lines]; the library's scenes are $NAMES (default a b).
NAMES="a b"
write_config() {
  local file=$1 out=$2
  {
    echo "bin: $BIN"
    echo "out: $out"
    echo "scenes:"
    for name in $NAMES; do
      echo "  $name: {input: $WORK/scenes/$name/cornell-box.json, photons: $PHOTONS, shards: $SHARDS, bounces: $BOUNCES, seed: $SEED}"
    done
    shift 2
    for line in "$@"; do echo "$line"; done
    echo "preview: {width: 48, height: 48, spp: 1, mode: direct+photons, backend: cpu}"
    echo "threads: {geometry: 2, shoot: 1, merge: 1, photons: 2, render: 2}"
  } > "$file"
}

# direct_chain CARD DIR [N SHARDS]: one scene through the tools by hand, as the pipeline should.
direct_chain() {
  local card=$1 dir=$2 n=${3:-$PHOTONS}
  mkdir -p "$dir"
  "$BIN/kdpm-build-geometry" "$card" -o "$dir/scene.kdg" --quiet
  "$BIN/kdpm-shoot-photons" "$dir/scene.kdg" -n "$n" --bounces "$BOUNCES" --seed "$SEED" -o "$dir/scene.kdph" --quiet
  "$BIN/kdpm-build-photons" "$dir/scene.kdph" -o "$dir/scene.kdp" --quiet
  "$BIN/kdpm-render" "$dir/scene.kdg" "$dir/scene.kdp" -o "$dir/preview.png" --width 48 --height 48 --spp 1 \
    --mode direct+photons --backend cpu --quiet
}

# same_files DIR1 DIR2 FILE...: fails naming the first file that differs.
same_files() {
  local one=$1 two=$2 f
  shift 2
  for f in "$@"; do
    cmp -s "$one/$f" "$two/$f" || { echo "FAIL: $one/$f and $two/$f differ"; return 1; }
  done
}

OUTPUTS="scene.kdg scene.kdph scene.kdp preview.png validated.txt"
