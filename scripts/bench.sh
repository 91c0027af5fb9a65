#!/usr/bin/env bash
# Benchmarks: BSDF micro-benchmarks, then fixed scenes rendered with 1 thread and all threads.
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
columba="$build/columba"
shared="$root/../shared/reference/scenes"
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

if [ -x "$build/columba_bench" ]; then
  echo "== BSDF micro-benchmarks"
  "$build/columba_bench" --benchmark_min_time=0.5
fi

# name | scene | extra arguments
scenes=(
  "spheres|$root/bench/scenes/spheres.xml|"
)
[ -f "$shared/simulation1.xml" ] && scenes+=("simulation1 (256x256, 64 spp)|$shared/simulation1.xml|-D res=256 -D spp=64")
# The reference neck scene on a dense generated patch as the paper's (4,320 barbs of 64 vertices;
# 18 feathers give 4,248), 1024x768, 16 spp, and the default scene's neck (60 feathers) with our
# own scene.
"$columba" feather --neck --feathers 18 --binary -o "$out/patch.ply" > /dev/null
"$columba" feather --neck --binary -o "$out/neck.ply" > /dev/null
if [ -f "$shared/neck.xml" ]; then
  mkdir -p "$out/reference/feathers"
  cp "$shared/neck.xml" "$out/reference/"
  ln -sf "$out/patch.ply" "$out/reference/feathers/feathers.ply"
  scenes+=("reference neck.xml, 18 feathers, 16 spp|$out/reference/neck.xml|-D spp=16")
fi
scenes+=("neck_direction1 (800x600, 16 spp)|$root/scenes/neck_direction1.xml|-D feathers=$out/neck.ply -D width=800 -D height=600 -D spp=16")

echo "== Scenes (threads: 1 and $(nproc))"
printf '%-36s %8s %10s %14s %12s\n' scene threads seconds "Msamples/s" "Mrays/s"
for entry in "${scenes[@]}"; do
  IFS='|' read -r name scene args <<< "$entry"
  for threads in 1 "$(nproc)"; do
    # shellcheck disable=SC2086
    line=$("$columba" render "$scene" -o "$out/bench.exr" --threads "$threads" $args 2>/dev/null | tail -1)
    secs=$(sed -E 's/.*: ([0-9.]+) s,.*/\1/' <<< "$line")
    sps=$(sed -E 's/.* ([0-9.]+) M samples\/s.*/\1/' <<< "$line")
    rps=$(sed -E 's/.* ([0-9.]+) M rays\/s.*/\1/' <<< "$line")
    printf '%-36s %8s %10s %14s %12s\n' "$name" "$threads" "$secs" "$sps" "$rps"
  done
done
