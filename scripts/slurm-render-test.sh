#!/usr/bin/env bash
# The Slurm test: run inside a cluster (scripts/slurm-test-cluster.sh, which sets SLURM_CONF):
#
#   scripts/slurm-test-cluster.sh scripts/slurm-render-test.sh BUILD/columba
#
# 1. renders a 3-frame sweep x 4 parts of a small feather scene through `columba slurm --submit`,
#    waits for the render array and the merge job (at most TIMEOUT seconds, 300 by default),
#    and checks every merged frame is bit-identical to the same frame rendered here in one piece;
# 2. deletes one piece and one merged frame, reruns `columba slurm --submit`, and checks that it
#    resubmits exactly that piece, and that the frame comes back bit-identical;
# 3. stops a long task with SIGTERM (as Slurm's time limit does), and checks its piece is left as
#    .partial (Status: interrupted), the merge job never ran, and `columba merge` names the piece.
# Prints the job ids, the time of every task and the test's duration.
set -euo pipefail
columba=$(realpath "$1")
root=$(cd "$(dirname "$0")/.." && pwd)
timeout=${TIMEOUT:-300}
: "${SLURM_CONF:?run this inside scripts/slurm-test-cluster.sh}"
work=$(mktemp -d /tmp/columba-slurm-test.XXXXXX)
trap 'rm -rf "$work"' EXIT
cd "$work"
started=$(date +%s)
fail() {
  echo "FAIL: $*" >&2
  for log in "$work"/*/logs/*.log; do
    [ -f "$log" ] && { echo "--- $log" >&2; tail -n 5 "$log" >&2; }
  done
  exit 1
}

# Waits until none of the jobs (ids, comma-separated) is queued or running.
wait_for() {
  local deadline=$(($(date +%s) + timeout))
  while [ -n "$(squeue -h -o %i -j "$1" 2> /dev/null)" ]; do
    [ "$(date +%s)" -lt "$deadline" ] || { squeue >&2; fail "jobs $1 still queued or running after ${timeout} s"; }
    sleep 1
  done
}

"$columba" feather --single -o feather.ply > /dev/null
scene=(
  "$root/scenes/feather_linear_light.xml" -D feather=feather.ply -D res=96 -D spp=8
  --sweep angle=0:40:20 --frames 'la{angle:03}.exr'
)
angles=(0 20 40)
mkdir -p local

# --- 1. the sweep through Slurm ---------------------------------------------------------------
"$columba" slurm "${scene[@]}" --parts 4 --cpus-per-task 1 --time 10:00 --out-dir sweep --submit | tee submit.txt
render_job=$(awk '/^render job:/ { print $3 }' submit.txt)
merge_job=$(awk '/^merge job:/ { print $3 }' submit.txt)
[ -n "$render_job" ] && [ -n "$merge_job" ] || fail "columba slurm printed no job ids"
wait_for "$render_job,$merge_job"
for angle in "${angles[@]}"; do
  name=$(printf 'la%03d' "$angle")
  [ -f "sweep/$name.exr" ] || fail "the merge job wrote no sweep/$name.exr"
  "$columba" render "${scene[0]}" -D feather=feather.ply -D res=96 -D spp=8 -D angle="$angle" -o "local/$name.exr" \
    > /dev/null 2>&1 || fail "the local render of angle $angle failed"
  "$columba" compare "sweep/$name.exr" "local/$name.exr" || fail "frame $name through Slurm differs from the local render"
done
grep -q '"status": "done"' sweep/manifest.json || fail "the manifest records no frame as done"
echo "Task times (job $render_job):"
grep -h "^columba task .*status" sweep/logs/render_"$render_job"_*.log | sort -t' ' -k3,3n | sed 's/^/  /'

# --- 2. resubmitting only what is missing -----------------------------------------------------
rm sweep/parts/la020.part3of4.exr sweep/la020.exr sweep/la020.png
"$columba" slurm "${scene[@]}" --parts 4 --cpus-per-task 1 --time 10:00 --out-dir sweep --submit | tee resubmit.txt
grep -q "array tasks 6)" resubmit.txt || fail "the rerun did not resubmit exactly task 6 (frame 1, part 3/4)"
wait_for "$(awk '/^render job:/ { print $3 }' resubmit.txt),$(awk '/^merge job:/ { print $3 }' resubmit.txt)"
"$columba" compare sweep/la020.exr local/la020.exr || fail "the resubmitted frame differs from the local render"
"$columba" slurm "${scene[@]}" --parts 4 --out-dir sweep | grep -q "Nothing to do" || fail "a finished sweep still has work"

# --- 3. a task stopped by SIGTERM, as at its time limit ---------------------------------------
long=("$root/scenes/feather_linear_light.xml" -D feather=feather.ply -D res=64 --spp 4000000)
"$columba" slurm "${long[@]}" --parts 2 --out-dir stopped --submit > stopped.txt
stopped_job=$(awk '/^render job:/ { print $3 }' stopped.txt)
stopped_merge=$(awk '/^merge job:/ { print $3 }' stopped.txt)
deadline=$(($(date +%s) + 60))
until grep -qs "^Rendering" stopped/logs/render_"$stopped_job"_0.log; do
  [ "$(date +%s)" -lt "$deadline" ] || fail "task 0 of job $stopped_job did not start rendering"
  sleep 0.5
done
sleep 1
scancel --full --signal=TERM "${stopped_job}_0"
scancel "${stopped_job}_1"
wait_for "$stopped_job,$stopped_merge"
piece=stopped/parts/feather_linear_light.part1of2
[ -f "$piece.partial.exr" ] || fail "the stopped task left no $piece.partial.exr"
[ ! -f "$piece.exr" ] || fail "the stopped task left $piece.exr, as if it were done"
grep -qa "interrupted" "$piece.partial.exr" || fail "$piece.partial.exr is not marked interrupted"
[ ! -f stopped/feather_linear_light.exr ] || fail "the merge job ran although a task failed"
if "$columba" merge --manifest stopped/manifest.json > merge.txt 2>&1; then fail "merge succeeded without its pieces"; fi
grep -q "part 1/2 was interrupted" merge.txt || { cat merge.txt >&2; fail "merge did not name the interrupted part"; }
rm -f stopped/parts/feather_linear_light.part2of2.partial.exr  # (cancelled too; a part that never ran:)
"$columba" merge --manifest stopped/manifest.json > merge.txt 2>&1 && fail "merge succeeded without its pieces"
grep -q "part 2/2 is missing" merge.txt || { cat merge.txt >&2; fail "merge did not name the missing part"; }
"$columba" slurm "${long[@]}" --parts 2 --out-dir stopped | grep -q "2 to render" || fail "the rerun does not plan both parts"

echo "PASS: Slurm sweep (3 frames x 4 parts) bit-identical to local renders; resubmission, SIGTERM and merge errors" \
  "checked in $(($(date +%s) - started)) s"
