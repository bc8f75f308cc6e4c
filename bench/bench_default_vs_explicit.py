#!/usr/bin/env python3
"""The default scheme against the explicit one over every shipped scene and every fuzz-corpus
scene that runs: whether the default finishes wherever the explicit scheme does, the two peaks,
what the default says of its own (peak_converged, the snap check's refined peak), and the CPU
of each. Each scene runs at most --duration simulated seconds (its [simulation] duration cut to
that) with its rows as given, each run at most --timeout seconds of wall time.

    /usr/bin/python3 bench/bench_default_vs_explicit.py --cablefilm build/cablefilm

Prints one line per scene and a summary: scenes the explicit scheme finished and the default
did not (the defect this guards against), and the largest relative peak differences.
"""
import argparse
import pathlib
import re
import resource
import subprocess
import sys
import tempfile


def cut_duration(text, seconds):
    """The scene's text with its simulated duration at most `seconds`, and with the integrator
    set by the caller: None if it is not a TOML scene with a [simulation] table."""
    m = re.search(r"(?m)^\[simulation\]\s*$", text)
    if not m:
        return None
    body_end = re.search(r"(?m)^\[", text[m.end():])
    end = m.end() + (body_end.start() if body_end else len(text) - m.end())
    body = text[m.end():end]
    d = re.search(r"(?m)^duration\s*=\s*([0-9.eE+-]+)", body)
    if d:
        try:
            value = min(float(d.group(1)), seconds)
        except ValueError:
            return None
        body = body[:d.start()] + f"duration = {value}" + body[d.end():]
    body = re.sub(r"(?m)^integrator\s*=.*$", "", body)
    return text[:m.end()] + body + text[end:]


def run(cablefilm, scene, out, timeout):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    try:
        p = subprocess.run([cablefilm, "run", str(scene), "--out", str(out), "--no-film"],
                           capture_output=True, text=True, timeout=timeout)
        rc = p.returncode
        tail = (p.stderr.strip().splitlines() or [""])[-1]
    except subprocess.TimeoutExpired:
        rc, tail = "timeout", ""
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    report = {}
    path = out / "run_report.toml"
    if rc == 0 and path.exists():
        for line in path.read_text().splitlines():
            m = re.match(r"(\w+)\s*=\s*([^#]+)", line)
            if m:
                report[m.group(1)] = m.group(2).strip()
    return rc, after.ru_utime - before.ru_utime, report, tail


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--cablefilm", required=True)
    ap.add_argument("--source-dir", default=str(pathlib.Path(__file__).resolve().parent.parent))
    ap.add_argument("--duration", type=float, default=10.0)
    ap.add_argument("--timeout", type=float, default=120.0)
    args = ap.parse_args()
    src = pathlib.Path(args.source_dir)
    scenes = sorted((src / "scenes").glob("*.toml")) + sorted((src / "tests/fuzz/corpus").iterdir())
    failures, differences = [], []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        for scene in scenes:
            try:
                text = scene.read_text()
            except (UnicodeDecodeError, IsADirectoryError):
                continue
            cut = cut_duration(text, args.duration)
            if cut is None:
                continue
            result = {}
            for scheme in ("default", "explicit"):
                body = cut if scheme == "default" else cut.replace(
                    "[simulation]", '[simulation]\nintegrator = "explicit"', 1)
                f = tmp / f"{scene.stem}_{scheme}.toml"
                f.write_text(body)
                # Relative paths in the scene (tables of motion) resolve from its own folder.
                for extra in scene.parent.glob("*.csv"):
                    target = tmp / extra.name
                    if not target.exists():
                        target.write_bytes(extra.read_bytes())
                result[scheme] = run(args.cablefilm, f, tmp / f"out_{scene.stem}_{scheme}",
                                     args.timeout)
            (rd, cd, repd, taild), (re_, ce, repe, taile) = result["default"], result["explicit"]
            if rd != 0 and re_ != 0:
                continue  # neither runs: a refused or impossible scene, not this comparison
            pd, pe = repd.get("peak_tension"), repe.get("peak_tension")
            line = (f"{scene.parent.name}/{scene.name}: default rc={rd} cpu={cd:.2f}s "
                    f"peak={pd} converged={repd.get('peak_converged')} "
                    f"refined={repd.get('peak_refined')}; explicit rc={re_} cpu={ce:.2f}s peak={pe}")
            print(line, flush=True)
            if re_ == 0 and rd != 0:
                failures.append(f"{scene.name}: {taild}")
            try:
                if pd and pe and float(pe) > 0:
                    differences.append((abs(float(pd) - float(pe)) / float(pe), scene.name))
            except ValueError:
                pass
    print(f"\nthe explicit scheme finished and the default did not: {len(failures)}")
    for f in failures:
        print("  " + f)
    differences.sort(reverse=True)
    print("largest peak differences (|default - explicit| / explicit):")
    for d, name in differences[:10]:
        print(f"  {d:.4f} {name}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
