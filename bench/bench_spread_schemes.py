#!/usr/bin/python3
"""The explicit scheme against the default on scenes/spread_mooring.toml, converged in links.

Each line's links multiplied by 1, 2 and 4 (--factors), the scene run as it is (the default:
implicit steps, explicit ones through snaps) and with integrator = "explicit", its 60 s written
every 0.1 s (the scene's 0.5 s would sample the peaks coarsely). Prints for each run its CPU
time and each fairlead's peak load (the largest |force| of points.csv over the rows: what the
fairlead holds), then the gap between the schemes at each refinement and the change of each
scheme's peaks from one refinement to the next (how converged in links they are). Asserts
nothing.

    /usr/bin/python3 bench/bench_spread_schemes.py [--cablefilm build/cablefilm] [--factors 1 2 4]
"""
import argparse
import csv
import math
import pathlib
import re
import subprocess
import tempfile
import time

SOURCE = pathlib.Path(__file__).resolve().parent.parent
FAIRLEADS = ("fairlead1", "fairlead2", "fairlead3")


def scene_text(factor, explicit):
    text = (SOURCE / "scenes" / "spread_mooring.toml").read_text()
    text = re.sub(r"^segments = (\d+)", lambda m: f"segments = {int(m.group(1)) * factor}", text,
                  flags=re.M)
    text = text.replace("film = true", "film = false")
    text = text.replace("[output]\n", "[output]\n").replace("interval = 0.5", "interval = 0.1")
    if explicit:
        text = text.replace("[simulation]\n", '[simulation]\nintegrator = "explicit"\n')
    return text


def run(program, folder, factor, explicit):
    name = f"x{factor}_{'explicit' if explicit else 'default'}"
    scene = folder / f"{name}.toml"
    scene.write_text(scene_text(factor, explicit))
    start = time.monotonic()
    done = subprocess.run([program, "run", str(scene), "--no-film", "--out", str(folder / name)],
                          capture_output=True, text=True)
    wall = time.monotonic() - start
    if done.returncode != 0:
        raise SystemExit(f"{name}: exit {done.returncode}: {done.stderr[-800:]}")
    cpu = float(re.search(r"^computer_time = ([0-9.eE+-]+)",
                          (folder / name / "run_report.toml").read_text(), re.M).group(1))
    peaks = {p: 0.0 for p in FAIRLEADS}
    with open(folder / name / "points.csv") as f:
        for row in csv.DictReader(f):
            if row["point"] in peaks:
                load = math.hypot(float(row["fx"]), float(row["fy"]), float(row["fz"]))
                peaks[row["point"]] = max(peaks[row["point"]], load)
    return {"name": name, "cpu": cpu, "wall": wall, "peaks": peaks}


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cablefilm", default=str(SOURCE / "build" / "cablefilm"))
    parser.add_argument("--factors", type=int, nargs="+", default=[1, 2, 4])
    args = parser.parse_args()
    results = {}
    with tempfile.TemporaryDirectory() as tmp:
        for factor in args.factors:
            for explicit in (False, True):
                r = run(args.cablefilm, pathlib.Path(tmp), factor, explicit)
                results[(factor, explicit)] = r
                print(f"{r['name']:>14}: {r['cpu']:8.2f} s of simulation ({r['wall']:.1f} s wall); "
                      + ", ".join(f"{p} {r['peaks'][p]:.6g} N" for p in FAIRLEADS), flush=True)
    print("\nexplicit against the default, (explicit - default) / default:")
    for factor in args.factors:
        d, e = results[(factor, False)]["peaks"], results[(factor, True)]["peaks"]
        print(f"  links x{factor}: " + ", ".join(f"{p} {(e[p] - d[p]) / d[p]:+.3%}" for p in FAIRLEADS))
    print("\neach scheme's peaks from one refinement to the next:")
    for a, b in zip(args.factors, args.factors[1:]):
        for explicit in (False, True):
            pa, pb = results[(a, explicit)]["peaks"], results[(b, explicit)]["peaks"]
            print(f"  {'explicit' if explicit else 'default':>8} x{a} -> x{b}: "
                  + ", ".join(f"{p} {(pb[p] - pa[p]) / pb[p]:+.3%}" for p in FAIRLEADS))


if __name__ == "__main__":
    main()
