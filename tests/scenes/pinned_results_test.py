#!/usr/bin/env python3
"""Every shipped scene (scenes/*.toml) gives the results pinned in tests/scenes/pinned/: its
timeseries.csv and the steps its run_report.toml counts (issue 18: results that do not change
as the code is reshaped; issue 19: a 2D scene's results the same on the 3D core).

Each scene is run as a user runs it (`cablefilm run SCENE --no-film`) and compared row by row:
the same rows and times; positions within 1e-9 m, the tensions within 1e-9 of the run's peak
tension, the link holding the largest tension the same unless two links are within that
tolerance of each other; the same steps, rejected steps and Newton iterations. The tolerance:
the pins were the program's own results to the last bit when they were made (every value
printed with 10 to 12 significant digits); 1e-9 of the peak allows only the round-off of an
arithmetic reordered (3D vectors with z = 0, sums in another order), about 1e-13 of the
peak, with a margin, while a changed step or a changed force moves tensions by far more
(the smallest change of a scheme's tolerance moves P63's peak by 1e-6 of it).

`--update` writes the pins anew from this build (say why in the commit).
"""
import argparse
import csv
import gzip
import io
import os
import pathlib
import re
import subprocess
import sys
import tempfile

STEP_KEYS = ("steps", "rejected_steps", "newton_iterations")


def run(cablefilm, scene, out):
    done = subprocess.run([cablefilm, "run", str(scene), "--no-film", "--out", str(out)],
                          capture_output=True, text=True, timeout=900)
    if done.returncode != 0:
        raise RuntimeError(f"{scene.name}: cablefilm run failed ({done.returncode}): "
                           f"{done.stderr.strip()[-400:]}")
    series = (out / "timeseries.csv").read_text()
    report = (out / "run_report.toml").read_text()
    steps = {k: int(re.search(rf"^{k} = (\d+)", report, re.M).group(1)) for k in STEP_KEYS}
    return series, steps


def rows(text):
    return list(csv.DictReader(io.StringIO(text)))


def compare(name, got, want, got_steps, want_steps):
    problems = []
    if got_steps != want_steps:
        problems.append(f"steps {got_steps}, pinned {want_steps}")
    a, b = rows(got), rows(want)
    if len(a) != len(b):
        return problems + [f"{len(a)} rows, pinned {len(b)}"]
    peak = max(float(r["tension_max"]) for r in b)
    worst = {"position": 0.0, "tension": 0.0}
    for ra, rb in zip(a, b):
        if ra["t"] != rb["t"]:
            problems.append(f"row at t = {rb['t']} s is at t = {ra['t']} s")
            break
        for key in ("x_end", "y_end", "z_end"):
            if key in rb:
                worst["position"] = max(worst["position"], abs(float(ra[key]) - float(rb[key])))
        for key in ("tension_start", "tension_end", "tension_max"):
            worst["tension"] = max(worst["tension"], abs(float(ra[key]) - float(rb[key])))
        if ra["link_max"] != rb["link_max"] and \
                abs(float(ra["tension_max"]) - float(rb["tension_max"])) > 1e-9 * peak:
            problems.append(f"t = {rb['t']} s: the largest tension in link {ra['link_max']}, "
                            f"pinned {rb['link_max']}")
            break
    if worst["position"] > 1e-9:
        problems.append(f"an end's position differs by {worst['position']:.3g} m (bound 1e-9 m)")
    if worst["tension"] > 1e-9 * peak:
        problems.append(f"a tension differs by {worst['tension']:.3g} N = "
                        f"{worst['tension'] / peak:.3g} of the peak (bound 1e-9)")
    print(f"{'FAIL' if problems else 'ok'}: {name}: {len(a)} rows, steps {got_steps}, largest "
          f"differences {worst['position']:.2g} m, {worst['tension'] / peak:.2g} of the peak "
          f"{peak:.6g} N")
    return problems


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cablefilm", required=True)
    parser.add_argument("--source-dir", required=True, type=pathlib.Path)
    parser.add_argument("--update", action="store_true")
    args = parser.parse_args()
    pinned = args.source_dir / "tests" / "scenes" / "pinned"
    scenes = sorted((args.source_dir / "scenes").glob("*.toml"))
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        for scene in scenes:
            name = scene.stem
            series, steps = run(args.cablefilm, scene, pathlib.Path(tmp) / name)
            pin = pinned / f"{name}.timeseries.csv.gz"
            pin_steps = pinned / f"{name}.steps"
            if args.update:
                with gzip.open(pin, "wt", compresslevel=9) as f:
                    f.write(series)
                pin_steps.write_text("".join(f"{k} = {v}\n" for k, v in steps.items()))
                print(f"pinned {name}: {steps}")
                continue
            if not pin.exists():
                failures.append(f"{name}: no pin (tests/scenes/pinned/{pin.name}): run with --update")
                continue
            with gzip.open(pin, "rt") as f:
                want = f.read()
            want_steps = {m.group(1): int(m.group(2))
                          for m in re.finditer(r"^(\w+) = (\d+)$", pin_steps.read_text(), re.M)}
            failures += [f"{name}: {p}" for p in compare(name, series, want, steps, want_steps)]
    for f in failures:
        print("FAIL:", f)
    print(f"{'FAIL' if failures else 'ok'}: {len(scenes)} shipped scenes against their pins")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
