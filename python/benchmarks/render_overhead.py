#!/usr/bin/env python3
"""The cost of rendering through Python against the command line, on the same scene, seed and
sample count: the CLI's render time (what `columba render` reports) against the wall time of
columba.render(), alternating the two, the median of --repeats runs each; and, less disturbed
by other work on the machine, the CPU time of the whole `columba render` process (loading and
writing included) against that of the columba.render() call.

    PYTHONPATH=build/python python3 python/benchmarks/render_overhead.py --columba build/columba \
        [--scene examples/tiny_feather.xml] [-D res=320] [-D spp=64] [--repeats 5] [--threads N]
"""
import argparse
import pathlib
import os
import re
import resource
import statistics
import subprocess
import tempfile
import time

import columba

parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
parser.add_argument("--columba", required=True, help="the columba executable")
parser.add_argument("--scene", default=str(pathlib.Path(__file__).resolve().parents[2] / "examples" / "tiny_feather.xml"))
parser.add_argument("-D", dest="defines", action="append", default=[], help="name=value, as for columba render")
parser.add_argument("--repeats", type=int, default=5)
parser.add_argument("--threads", type=int, default=None)
args = parser.parse_args()
defines = dict(d.split("=", 1) for d in args.defines)

cli_args = [args.columba, "render", args.scene, "--seed", "0"]
for d in args.defines:
    cli_args += ["-D", d]
if args.threads:
    cli_args += ["--threads", str(args.threads)]
scene = columba.load_file(args.scene, **defines)

cli_times, py_times, py_inner, cli_cpu, py_cpu = [], [], [], [], []


def cpu_seconds(who):
    r = resource.getrusage(who)
    return r.ru_utime + r.ru_stime


with tempfile.TemporaryDirectory() as tmp:
    for _ in range(args.repeats):
        children = cpu_seconds(resource.RUSAGE_CHILDREN)
        out = subprocess.run(cli_args + ["-o", f"{tmp}/cli.exr"], capture_output=True, text=True, check=True).stdout
        cli_cpu.append(cpu_seconds(resource.RUSAGE_CHILDREN) - children)
        cli_times.append(float(re.search(r": ([0-9.]+) s,", out).group(1)))
        start, own = time.perf_counter(), cpu_seconds(resource.RUSAGE_SELF)
        image, stats = columba.render(scene, seed=0, threads=args.threads, stats=True)
        py_times.append(time.perf_counter() - start)
        py_cpu.append(cpu_seconds(resource.RUSAGE_SELF) - own)
        py_inner.append(stats["seconds"])
    same = (columba.read_image(f"{tmp}/cli.exr") == image).all()

cli, py, inner, ccpu, pcpu = (statistics.median(t) for t in (cli_times, py_times, py_inner, cli_cpu, py_cpu))
print(f"scene {args.scene} {scene.width}x{scene.height}, {stats['spp']} spp, {args.repeats} runs each")
print(f"CLI render time (median):        {cli:.3f} s   runs: {' '.join(f'{t:.3f}' for t in cli_times)}")
print(f"columba.render wall time (median): {py:.3f} s   runs: {' '.join(f'{t:.3f}' for t in py_times)}")
print(f"  of which the renderer's own time: {inner:.3f} s")
print(f"CPU time (median): CLI process {ccpu:.3f} s, columba.render {pcpu:.3f} s")
print(f"overhead of Python: wall {100 * (py / cli - 1):+.2f} %, CPU {100 * (pcpu / ccpu - 1):+.2f} %, "
      f"wrapper (wall - renderer) {1000 * (py - inner):.1f} ms; images identical: {bool(same)}")
