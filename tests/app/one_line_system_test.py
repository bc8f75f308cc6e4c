"""A line alone is a system of one line: the same bytes either way.

Every shipped scene of one line (a [cable] between [ends]) is written again as a system of one
[[line]] between two [[point]]s, its line and points given names of their own; both run (cut to
a few seconds, no film) and every result file must be the same: equilibrium.csv and
timeseries.csv byte for byte, run_report.toml but for the computer time, results.nc's
dimensions, variables (values, types, attributes) and global attributes but for the scene's
file and text. The reverse for MoorDyn: a MoorDyn file of one line between a Fixed and a Coupled
point (tests/scenes/moordyn/one_leg.txt), and one whose far end is a Free point of no mass
(hanging_chain.txt), run as they are, against the scene `convert` writes of them turned into a
[cable] scene.

Needs Debian's python3-netcdf4 (to read results.nc); without it, status 77 (skipped).
"""
import argparse
import math
import pathlib
import shutil
import subprocess
import sys
import tomllib

try:
    import netCDF4
    import numpy
except ImportError:
    print("skipped: no netCDF4 or numpy in this Python")
    sys.exit(77)

SHORT = 4.0  # [s] simulated: every scheme's steps, snaps and statics, at little cost


# ---- TOML written back (the scenes use tables, arrays of tables, numbers, strings, arrays) ----

def value(v):
    if isinstance(v, bool):
        return "true" if v else "false"
    if isinstance(v, (int, float)):
        return repr(v) if not isinstance(v, float) or math.isfinite(v) else str(v)
    if isinstance(v, str):
        return '"' + v.replace("\\", "\\\\").replace('"', '\\"') + '"'
    if isinstance(v, list):
        return "[" + ", ".join(value(x) for x in v) + "]"
    raise TypeError(v)


def is_table_array(v):
    return isinstance(v, list) and v and all(isinstance(x, dict) for x in v)


def emit(table, prefix, out):
    for k, v in table.items():
        if not isinstance(v, dict) and not is_table_array(v):
            out.append(f"{k} = {value(v)}")
    for k, v in table.items():
        name = f"{prefix}.{k}" if prefix else k
        if isinstance(v, dict):
            out.append(f"\n[{name}]")
            emit(v, name, out)
        elif is_table_array(v):
            for item in v:
                out.append(f"\n[[{name}]]")
                emit(item, name, out)


def dumps(scene):
    out = []
    emit(scene, "", out)
    return "\n".join(out) + "\n"


# ---- The same line written both ways ----

def as_system(scene):
    """[cable] + [ends] as one [[line]] "leg" from [[point]] "anchor" to "fairlead"."""
    s = dict(scene)
    cable = s.pop("cable")
    ends = s.pop("ends")
    line = {"name": "leg", "start": "anchor", "end": "fairlead"}
    line.update(cable)
    s["point"] = [{"name": "anchor", **ends["start"]}, {"name": "fairlead", **ends["end"]}]
    s["line"] = [line]
    return s


def as_cable(scene):
    """A system of one [[line]] between two [[point]]s as [cable] + [ends]."""
    s = dict(scene)
    (line,) = s.pop("line")
    points = {p["name"]: {k: v for k, v in p.items() if k != "name"} for p in s.pop("point")}
    s["cable"] = {k: v for k, v in line.items() if k not in ("name", "start", "end")}
    s["ends"] = {"start": points[line["start"]], "end": points[line["end"]]}
    return s


def shortened(scene):
    s = dict(scene)
    sim = dict(s.get("simulation", {}))
    sim["duration"] = min(sim.get("duration", SHORT), SHORT)
    s["simulation"] = sim
    out = dict(s.get("output", {}))
    out["film"] = False
    s["output"] = out
    return s


# ---- Running and comparing ----

def run(cablefilm, scene, out):
    done = subprocess.run([cablefilm, "run", str(scene), "--no-film", "--out", str(out)],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise SystemExit(f"FAIL: {scene}: exit {done.returncode}: {done.stderr[-800:]}")


def same_results(a, b, what):
    """The differences between two output folders, named."""
    failures = []
    names_a = sorted(p.name for p in a.iterdir())
    names_b = sorted(p.name for p in b.iterdir())
    if names_a != names_b:
        return [f"{what}: files {names_a} against {names_b}"]
    for name in ("equilibrium.csv", "timeseries.csv"):
        if (a / name).read_bytes() != (b / name).read_bytes():
            failures.append(f"{what}: {name} differs")
    keep = lambda p: [l for l in p.read_text().splitlines()
                      if not l.startswith(("computer_time", "cpu_time"))]
    if keep(a / "run_report.toml") != keep(b / "run_report.toml"):
        failures.append(f"{what}: run_report.toml differs beyond the computer time")
    fa, fb = netCDF4.Dataset(a / "results.nc"), netCDF4.Dataset(b / "results.nc")
    try:
        dims = lambda f: {k: len(d) for k, d in f.dimensions.items()}
        if dims(fa) != dims(fb):
            failures.append(f"{what}: results.nc dimensions {dims(fa)} against {dims(fb)}")
        attrs = lambda o, skip=(): {k: str(o.getncattr(k)) for k in o.ncattrs() if k not in skip}
        if attrs(fa, ("scene", "scene_file")) != attrs(fb, ("scene", "scene_file")):
            failures.append(f"{what}: results.nc global attributes differ")
        if set(fa.variables) != set(fb.variables):
            failures.append(f"{what}: results.nc variables {sorted(fa.variables)} against "
                            f"{sorted(fb.variables)}")
        for v in sorted(set(fa.variables) & set(fb.variables)):
            x, y = fa[v], fb[v]
            if x.dtype != y.dtype or x.dimensions != y.dimensions or attrs(x) != attrs(y):
                failures.append(f"{what}: results.nc {v}: type, dimensions or attributes differ")
            elif not numpy.array_equal(numpy.ma.filled(x[:], numpy.nan),
                                       numpy.ma.filled(y[:], numpy.nan), equal_nan=True):
                failures.append(f"{what}: results.nc {v}: values differ")
    finally:
        fa.close()
        fb.close()
    return failures


def shipped_lines(args, tmp):
    failures = []
    scenes = sorted(p for p in (args.source_dir / "scenes").glob("*.toml")
                    if "cable" in tomllib.loads(p.read_text()))
    for csv in (args.source_dir / "scenes").glob("*.csv"):  # a table motion's file
        shutil.copy(csv, tmp / csv.name)
    for path in scenes:
        scene = shortened(tomllib.loads(path.read_text()))
        (tmp / f"{path.stem}_cable.toml").write_text(dumps(scene))
        (tmp / f"{path.stem}_system.toml").write_text(dumps(as_system(scene)))
        for form in ("cable", "system"):
            run(args.cablefilm, tmp / f"{path.stem}_{form}.toml", tmp / f"{path.stem}_{form}")
        found = same_results(tmp / f"{path.stem}_cable", tmp / f"{path.stem}_system", path.name)
        print(f"{path.name}: [cable] and one [[line]]: {'the same' if not found else 'DIFFER'}")
        failures += found
    if len(scenes) < 9:
        failures.append(f"only {len(scenes)} shipped scenes of one line found")
    return failures


def moordyn_files(args, tmp):
    failures = []
    for name in ("one_leg.txt", "hanging_chain.txt"):
        path = args.source_dir / "tests" / "scenes" / "moordyn" / name
        converted = subprocess.run([args.cablefilm, "convert", str(path)], capture_output=True,
                                   text=True, check=True).stdout
        cable = as_cable(tomllib.loads(converted))
        stem = pathlib.Path(name).stem
        (tmp / f"{stem}_cable.toml").write_text(dumps(cable))
        run(args.cablefilm, path, tmp / f"{stem}_moordyn")
        run(args.cablefilm, tmp / f"{stem}_cable.toml", tmp / f"{stem}_cable")
        found = same_results(tmp / f"{stem}_moordyn", tmp / f"{stem}_cable", name)
        print(f"{name}: the MoorDyn file and the [cable] scene: "
              f"{'the same' if not found else 'DIFFER'}")
        failures += found
    return failures


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cablefilm", required=True)
    parser.add_argument("--source-dir", required=True, type=pathlib.Path)
    parser.add_argument("--out-dir", required=True, type=pathlib.Path)
    args = parser.parse_args()
    shutil.rmtree(args.out_dir, ignore_errors=True)
    args.out_dir.mkdir(parents=True)
    failures = shipped_lines(args, args.out_dir) + moordyn_files(args, args.out_dir)
    for f in failures:
        print("FAIL:", f)
    print("FAIL" if failures else "ok")
    if not failures:
        shutil.rmtree(args.out_dir, ignore_errors=True)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
