#!/usr/bin/env bash
# Runs the libFuzzer targets built in BUILD_DIR, one after another, each for SECONDS:
#   fuzz/run.sh BUILD_DIR SECONDS [TARGET...]     (targets: scene ply_mesh feather_ply obj_mesh serialized_mesh sdf_grid exr_envmap hdr_envmap bitmap merge_piece manifest spectra_csv layer_text observer_table observer_definition medium_grid number_list)
# Each target's corpus grows in BUILD_DIR/fuzz/corpus/TARGET, seeded from fuzz/seeds/TARGET (small
# scenes, meshes, feathers written by `columba feather`, EXR images of every compression, images
# of every format stb_image reads, a piece of a split render, a manifest, a spectra table, observer tables and definitions), the
# project's scenes and examples, the inputs of tests/fuzz-regressions/TARGET, and feathers that
# $COLUMBA (build/columba by default; skipped when not built) generates. Findings go to BUILD_DIR/fuzz/findings/TARGET, logs to
# BUILD_DIR/fuzz/logs. Prints one line per target (executions, coverage, findings); exits non-zero
# when any target found a crash, leak, timeout or out-of-memory input.
set -uo pipefail
cd "$(dirname "$0")/.."
build=$1 seconds=$2
shift 2
targets=("$@")
[ ${#targets[@]} -eq 0 ] && targets=(scene ply_mesh feather_ply obj_mesh serialized_mesh sdf_grid exr_envmap hdr_envmap bitmap merge_piece manifest spectra_csv layer_text observer_table observer_definition medium_grid number_list)
work="$build/fuzz"
columba=${COLUMBA:-build/columba}
mkdir -p "$work/logs"

seed() {  # seed TARGET CORPUS
  local t=$1 corpus=$2
  cp -n fuzz/seeds/"$t"/* "$corpus"/ 2>/dev/null
  [ -d tests/fuzz-regressions/"$t" ] && cp -n tests/fuzz-regressions/"$t"/* "$corpus"/ 2>/dev/null
  case $t in
    scene)
      # Relative file names resolve against examples/: the scenes' feathers become the tiny one.
      for f in scenes/*.xml examples/*.xml; do
        { printf -- '-Dfeather=tiny_feather.ply\n-Dfeathers=tiny_feather.ply\n-Dspp=1\n'; cat "$f"; } \
          > "$corpus/project-$(basename "$f")"
      done ;;
    feather_ply)
      cp -n examples/tiny_feather.ply "$corpus"/
      if [ -x "$columba" ]; then
        "$columba" feather --single --barbs 1 -o "$corpus/generated-single.ply" > /dev/null 2>&1
        "$columba" feather --neck --feathers 2 --barbs 1 --binary -o "$corpus/generated-neck.ply" > /dev/null 2>&1
      fi ;;
  esac
  return 0
}

dict_of() {
  case $1 in scene) echo fuzz/dict/scene.dict ;; ply_mesh|feather_ply) echo fuzz/dict/ply.dict ;;
    obj_mesh) echo fuzz/dict/obj.dict ;; exr_envmap) echo fuzz/dict/exr.dict ;;
    serialized_mesh) echo fuzz/dict/serialized.dict ;; sdf_grid|medium_grid) echo fuzz/dict/vol.dict ;;
    hdr_envmap) echo fuzz/dict/hdr.dict ;; bitmap) echo fuzz/dict/bitmap.dict ;; merge_piece) echo fuzz/dict/piece.dict ;;
    manifest) echo fuzz/dict/manifest.dict ;; spectra_csv) echo fuzz/dict/spectra.dict ;;
    layer_text) echo fuzz/dict/layers.dict ;; observer_table|observer_definition) echo fuzz/dict/observer.dict ;;
    number_list) echo fuzz/dict/list.dict ;; esac
}

# Memory limits (MB: one allocation, the whole process). The image and piece readers check every
# declared size against the file's length before allocating: a few kilobytes of input must never
# take hundreds of megabytes.
limits_of() {
  case $1 in hdr_envmap|bitmap|merge_piece) echo "-malloc_limit_mb=512 -rss_limit_mb=1024" ;;
    *) echo "-malloc_limit_mb=2048 -rss_limit_mb=2560" ;; esac
}

status=0
printf '%-12s %8s %12s %8s %8s %s\n' target seconds executions edges features findings
for t in "${targets[@]}"; do
  binary="$build/fuzz_$t"
  [ -x "$binary" ] || { echo "$binary is missing (make fuzz builds it)"; status=1; continue; }
  corpus="$work/corpus/$t" findings="$work/findings/$t" log="$work/logs/$t.log"
  mkdir -p "$corpus" "$findings"
  seed "$t" "$corpus"
  start=$(date +%s)
  # -close_fd_mask=2: the readers' warnings are not shown (sanitizer reports still are).
  # shellcheck disable=SC2046  # the limits are two words
  "$binary" "$corpus" -dict="$(dict_of "$t")" -max_total_time="$seconds" -timeout=20 $(limits_of "$t") \
    -close_fd_mask=2 -print_final_stats=1 -artifact_prefix="$findings/" > "$log" 2>&1
  rc=$?
  elapsed=$(( $(date +%s) - start ))
  execs=$(grep -o 'stat::number_of_executed_units: [0-9]*' "$log" | tail -1 | awk '{print $2}')
  cov=$(grep -oE 'cov: [0-9]+' "$log" | tail -1 | awk '{print $2}')
  ft=$(grep -oE 'ft: [0-9]+' "$log" | tail -1 | awk '{print $2}')
  found=$(find "$findings" -type f \( -name 'crash-*' -o -name 'leak-*' -o -name 'timeout-*' -o -name 'oom-*' \) | wc -l)
  printf '%-12s %8s %12s %8s %8s %s\n' "$t" "$elapsed" "${execs:-?}" "${cov:-?}" "${ft:-?}" "$found"
  if [ $rc -ne 0 ] || [ "$found" -ne 0 ]; then
    status=1
    echo "  $t: exit $rc; findings in $findings, log $log"
  fi
done
exit $status
