#!/usr/bin/env python3
"""Equal-error benchmark: time to a clean image, against the paper's implementation.

For each scene a converged image is rendered once (two halves of REF_SPP with different seeds,
cached under CACHE, keyed by the scene's content and the settings), then the scene is rendered at
spp = 1, 2, 4, ..., MAX_SPP with a fixed thread count; for each render the wall time of the whole
`columba render` process and the relative RMSE against the converged image (each scene also
with --adaptive, from 4 spp, and the neck with one emitter sample, -D candidates=1, the paper's
estimator),
    relative RMSE = sqrt(mean((image - converged)^2)) / mean(converged),
are printed, and the times to reach 5 % and 2 % are interpolated on the log-log error-vs-time
line. The converged image's own error is estimated from its two halves (rmse(A - B) / 2) and
subtracted in quadrature ("corrected" column; the times use it). Then equal-spp timings. Before
and after the tables, the parallel efficiency of the thread count (a warning below 85 %: cores
shared with other guests make every time longer than the paper's were measured on free cores).

Usage: equal_error.py COLUMBA ROOT CACHE [WORK]
Environment: BENCH_THREADS (2), BENCH_MAX_SPP (256; per scene: BENCH_MAX_SPP_SIM,
BENCH_MAX_SPP_NECK), BENCH_REF_SPP_SIM (4096),
BENCH_REF_SPP_NECK (1024), BENCH_EE_REPEATS (1: runs per equal-spp row, the fastest is shown).
"""
import hashlib
import math
import os
import re
import subprocess
import sys
import tempfile
import time

import numpy as np

# Columba's Python module of the build that holds COLUMBA (BUILD/python).
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(sys.argv[1] if len(sys.argv) > 1 else ".")), "python"))
import columba as columba_module  # noqa: E402


# Below this, `threads` threads do measurably less than `threads` times one thread's work.
MIN_PARALLEL_EFFICIENCY = 0.85


def read_exr_rgb(path):
    """An EXR the renderer wrote, as an H x W x 3 float64 array (read by Columba's Python module)."""
    return columba_module.read_image(path).astype(np.float64)


def render(columba, scene, defines, spp, seed, threads, output, options=()):
    cmd = [columba, "render", scene, "-o", output, "--spp", str(spp), "--seed", str(seed),
           "--threads", str(threads), *options]
    for d in defines:
        cmd += ["-D", d]
    start = time.perf_counter()
    proc = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    wall = time.perf_counter() - start
    if proc.returncode != 0:
        sys.exit(f"render failed ({' '.join(cmd)}):\n{proc.stderr}{proc.stdout}")
    m = re.search(r"^Rendered .*?: ([0-9.]+) s, ", proc.stdout, re.MULTILINE)
    return wall, float(m.group(1)) if m else float("nan")


def file_digest(h, path):
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 20), b""):
            h.update(block)


# What renders converge to, part of the cache key: a cached image from a renderer that converged
# to another image (before camera samples were splatted over their filter's footprint, border
# pixels were filtered over positions beyond the film, and the Gaussian was not windowed) is not
# reused.
CONVERGED_IMAGE_CONVENTION = "splatted camera samples; pixels over their filter's mass on the film"


def converged(columba, cache, name, scene, inputs, defines, ref_spp, threads, work):
    """The converged image (mean of two halves) and its own relative RMSE estimate."""
    h = hashlib.sha256(CONVERGED_IMAGE_CONVENTION.encode())
    for path in [scene] + inputs:
        file_digest(h, path)
    h.update(repr((sorted(defines), ref_spp)).encode())
    key = h.hexdigest()[:16]
    path = os.path.join(cache, f"{name}-{ref_spp}spp-{key}.npz")
    if os.path.exists(path):
        z = np.load(path)
        a, b, seconds = z["a"], z["b"], float(z["seconds"])
        print(f"  converged image: cached {path}")
    else:
        print(f"  converged image: rendering 2 x {ref_spp // 2} spp with {threads} threads "
              f"(cached in {path}) ...", flush=True)
        halves = []
        seconds = 0.0
        for seed in (1001, 1002):
            out = os.path.join(work, f"{name}-ref{seed}.exr")
            wall, _ = render(columba, scene, defines, ref_spp // 2, seed, threads, out)
            seconds += wall
            halves.append(read_exr_rgb(out))
        a, b = halves
        os.makedirs(cache, exist_ok=True)
        tmp = path + ".tmp.npz"
        np.savez_compressed(tmp, a=a, b=b, seconds=seconds)
        os.replace(tmp, path)
    ref = 0.5 * (a + b)
    mean = ref.mean()
    # Var(A - B) = 2 sigma^2 per half; the mean of the halves has sigma^2 / 2: a quarter.
    ref_mse = np.mean((a - b) ** 2) / 4.0
    print(f"  converged image: {ref_spp} spp ({seconds:.1f} s), its own relative RMSE "
          f"~{math.sqrt(ref_mse) / mean:.4f} (from its two halves)")
    return ref, mean, ref_mse


def time_to(points, target):
    """Time at which the error reaches target, from (spp, seconds, error) rows: log-log
    interpolation between the two renders around it; beyond the last render, its error scaled
    as spp^(-1/2) and the time per sample of the last two renders ("*")."""
    pts = [p for p in points if math.isfinite(p[2]) and p[2] > 0 and p[1] > 0]
    for (s0, t0, e0), (s1, t1, e1) in zip(pts, pts[1:]):
        if e0 >= target >= e1 and e0 != e1:
            f = (math.log(target) - math.log(e0)) / (math.log(e1) - math.log(e0))
            return math.exp(math.log(t0) + f * (math.log(t1) - math.log(t0))), " "
    if len(pts) < 2 or pts[-1][2] < target:
        return float("nan"), "?"
    (s0, t0, _), (s1, t1, e1) = pts[-2:]
    spp = s1 * (e1 / target) ** 2
    return t1 + (spp - s1) * max(t1 - t0, 0.0) / (s1 - s0), "*"


def paper_time(t0, e0, target):
    # The paper's one point extrapolated along error ~ time^(-1/2).
    return t0 * (e0 / target) ** 2


def equal_error(columba, cache, work, name, title, scene, inputs, defines, ref_spp, max_spp,
                threads, paper, options=(), min_spp=1):
    print(f"\n== Equal error: {title}" + (f", with {' '.join(options)}" if options else ""))
    ref, mean, ref_mse = converged(columba, cache, name, scene, inputs, defines, ref_spp,
                                   threads, work)
    print(f"{'spp':>6} {'wall_s':>8} {'render_s':>9} {'rel_RMSE':>9} {'corrected':>9} "
          f"{'var/sample':>10} {'non-finite_px':>13}")
    points = []
    timings = {}
    spp = min_spp
    while spp <= max_spp:
        out = os.path.join(work, f"{name}-{spp}.exr")
        wall, secs = render(columba, scene, defines, spp, 0, threads, out, options)
        img = read_exr_rgb(out)
        bad = int(np.count_nonzero(~np.isfinite(img).all(axis=-1)))
        with np.errstate(over="ignore", invalid="ignore"):
            mse = np.mean((img - ref) ** 2)
        raw = math.sqrt(mse) / mean
        corr = math.sqrt(max(mse - ref_mse, 0.0)) / mean
        points.append((spp, wall, secs, corr))
        timings[spp] = wall
        print(f"{spp:>6} {wall:>8.2f} {secs:>9.2f} {raw:>9.4g} {corr:>9.4g} "
              f"{corr * corr * spp:>10.4g} {bad:>13}", flush=True)
        spp *= 2
    pt, pe, pspp = paper
    print(f"  paper's code: relative RMSE {pe} at {pspp} spp in {pt} s (2 threads)")
    print(f"  {'target':>8} {'Columba_s':>10} {'(render)':>9} {'paper_s':>9} {'speed-up':>9}")
    for target in (0.05, 0.02):
        t, mark = time_to([(s, w, e) for s, w, _, e in points], target)
        r, rmark = time_to([(s, x, e) for s, _, x, e in points], target)
        p = paper_time(pt, pe, target)
        print(f"  {target:>8.0%} {t:>9.2f}{mark} {r:>8.2f}{rmark} {p:>9.2f} {p / t:>8.2f}x")
    print("  Columba_s: wall time of the process; (render): the renderer's own time, without "
          "scene loading and image writing; speed-up: of wall times.\n"
          "  * beyond the last render: its error scaled as spp^-1/2 at its time per sample; the "
          "paper's times: its one point scaled along error ~ time^-1/2")
    return timings


def report_parallel_efficiency(columba, scene, threads, work, when):
    """The paper's times were measured on cores nobody else used. Where this machine's cores are
    shared (another guest on the same physical cores, or their hyper-threads), each of several
    threads runs slower than one thread alone, and every wall time is inflated: the renderer's own
    time with `threads` threads against one thread on the same work shows it (not a slowdown of
    every thread alike). Measured before and after the tables, as the load of other guests changes."""
    if threads < 2:
        return
    out = os.path.join(work, "calibration.exr")
    defs = ["res=128"]
    one, many = [], []
    for _ in range(3):  # interleaved, the fastest of each: the load of other guests comes and goes
        one.append(render(columba, scene, defs, 64, 0, 1, out)[1])
        many.append(render(columba, scene, defs, 64, 0, threads, out)[1])
    efficiency = round(min(one) / (threads * min(many)), 2)  # as printed, so a printed 85 % does not warn
    print(f"  parallel efficiency {when}: {efficiency:.0%} ({os.path.basename(scene)} 128x128, 64 spp: "
          f"{min(one):.2f} s with 1 thread, {min(many):.2f} s with {threads})", flush=True)
    if efficiency < MIN_PARALLEL_EFFICIENCY:
        print(f"  WARNING: below {MIN_PARALLEL_EFFICIENCY:.0%}: this machine's cores are shared, so this "
              f"run's times are longer than on free cores and its speed-ups against the paper's times "
              f"understated; compare its times only with each other", flush=True)


def main():
    if len(sys.argv) < 4:
        sys.exit(__doc__)
    columba, root, cache = (os.path.abspath(a) for a in sys.argv[1:4])
    threads = int(os.environ.get("BENCH_THREADS", "2"))
    max_spp = int(os.environ.get("BENCH_MAX_SPP", "256"))
    max_sim = int(os.environ.get("BENCH_MAX_SPP_SIM", max_spp))
    max_neck = int(os.environ.get("BENCH_MAX_SPP_NECK", max_spp))
    ref_sim = int(os.environ.get("BENCH_REF_SPP_SIM", "4096"))
    ref_neck = int(os.environ.get("BENCH_REF_SPP_NECK", "1024"))
    repeats = int(os.environ.get("BENCH_EE_REPEATS", "1"))
    with tempfile.TemporaryDirectory() as tmp:
        work = sys.argv[4] if len(sys.argv) > 4 else tmp
        os.makedirs(work, exist_ok=True)
        print(f"Equal-error benchmark: {threads} threads, wall time of `columba render` "
              f"(scene loading and image writing included); load average now "
              f"{os.getloadavg()[0]:.1f} on {os.cpu_count()} cores")
        # The paper's simulation3 (a BSDF visualisation of the sampled barbule under a uniform
        # environment, BSDF sampling only) where the shared reference scenes are checked out,
        # else Columba's own version of it.
        sim3 = os.path.join(root, "../shared/reference/scenes/simulation3.xml")
        if not os.path.exists(sim3):
            sim3 = os.path.join(root, "scenes/bsdf_visualization_sampled.xml")
        sim3_defs = ["res=256"]
        sim3_title = f"simulation3-like: {os.path.relpath(sim3, root)}, 256x256 (BSDF sampling)"
        report_parallel_efficiency(columba, sim3, threads, work, "before the tables")
        t_sim3 = equal_error(columba, cache, work, "sim3", sim3_title, sim3, [], sim3_defs, ref_sim,
                             max_sim, threads, (5.34, 0.054, 64))
        equal_error(columba, cache, work, "sim3", sim3_title, sim3, [], sim3_defs, ref_sim, max_sim,
                    threads, (5.34, 0.054, 64), ("--adaptive",), 4)
        # A dense neck patch of Columba's own: the generator's neck with 18 feathers (seed 1):
        # 4,248 barbs of 64 vertices (the paper's patch: 4,320).
        patch = os.path.join(work, "patch.ply")
        subprocess.run([columba, "feather", "--neck", "--feathers", "18", "--seed", "1",
                        "--binary", "-o", patch], check=True, stdout=subprocess.DEVNULL)
        # Under the camera and lights of the paper's neck scene (its feathers are not ours).
        neck = os.path.join(root, "bench/neck_paper_lighting.xml")
        neck_defs = [f"feathers={patch}", "width=512", "height=384"]
        neck_title = ("dense neck patch: bench/neck_paper_lighting.xml on `columba feather --neck "
                      "--feathers 18` (4,248 barbs), 512x384")
        equal_error(columba, cache, work, "neck", neck_title, neck, [patch], neck_defs, ref_neck,
                    max_neck, threads, (65.0, 0.063, 64))
        equal_error(columba, cache, work, "neck", neck_title, neck, [patch], neck_defs, ref_neck,
                    max_neck, threads, (65.0, 0.063, 64), ("--adaptive",), 4)
        # With one emitter sample per vertex, the paper's estimator, instead of Columba's default
        # (3 candidates resampled at the barbules' first vertices): the same converged image,
        # which no estimator changes.
        equal_error(columba, cache, work, "neck", neck_title, neck, [patch], neck_defs, ref_neck, max_neck,
                    threads, (65.0, 0.063, 64), ("-D", "candidates=1"))

        print(f"\n== Equal spp ({threads} threads, fastest of {repeats})")
        sim1 = os.path.join(root, "../shared/reference/scenes/simulation1.xml")
        sim1_defs = ["res=256"]
        if not os.path.exists(sim1):
            sim1 = os.path.join(root, "scenes/bsdf_visualization_oblique.xml")
        rows = [("simulation1-like 256x256, 64 spp", sim1, sim1_defs, 64, 5.91),
                ("simulation3-like 256x256, 64 spp", sim3, sim3_defs, 64, 4.99),
                ("dense neck 1024x768, 16 spp", neck,
                 [f"feathers={patch}", "width=1024", "height=768"], 16, 66.2),
                ("  the same, one emitter sample", neck,
                 [f"feathers={patch}", "width=1024", "height=768", "candidates=1"], 16, 66.2)]
        print(f"{'scene':<36} {'Columba_s':>10} {'paper_s':>8} {'speed-up':>9}")
        for title, scene, defs, spp, paper in rows:
            runs = [render(columba, scene, defs, spp, 0, threads,
                           os.path.join(work, "eq.exr"))[0] for _ in range(repeats)]
            if scene == sim3 and spp in t_sim3:
                runs.append(t_sim3[spp])
            t = min(runs)
            print(f"{title:<36} {t:>10.2f} {paper:>8.2f} {paper / t:>8.2f}x", flush=True)
        print(f"  simulation1-like scene: {os.path.relpath(sim1, root)}")
        report_parallel_efficiency(columba, sim3, threads, work, "after the tables")


if __name__ == "__main__":
    main()
