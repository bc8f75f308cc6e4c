"""A driven body that turns (issue 20), end to end: tests/scenes/system/turning_platform.toml,
a platform yawed 4 degrees by a 7-column table (t, x, y, z, rx, ry, rz; joined linearly, so its
angle at any time is known by hand). Checks that
- every fairlead in points.csv is where the turn puts it, R(theta(t)) p with theta the rest
  orientation plus the table's angle at t, to 1e-9 m (points.csv prints 12 digits: 1e-10 m at
  these 20 m; the step puts a prescribed end exactly at its motion), and body.csv's ry column is
  that angle (to 1e-8 degrees: it prints 10 digits of about 14);
- the yaw moves the fairleads and changes the legs' pull on them (against the same run with the
  body still);
- a table without angles (four columns) and one with angle columns of zeros give the same
  results to the byte: a table with no turn is the old motion."""
import argparse
import csv
import io
import math
import pathlib
import shutil
import subprocess
import sys
import tempfile

SCENE = "turning_platform"
REST_YAW = 10.0  # the scene's orientation about y [deg]
LOCAL = {"fairlead1": (20.0, -10.0, 0.0), "fairlead2": (-10.0, -10.0, 17.321),
         "fairlead3": (-10.0, -10.0, -17.321)}  # [m], in the body's axes
ROWS = [(0.0, 0.0), (1.0, 0.0), (5.0, 4.0), (10.0, 4.0)]  # (t [s], yaw [deg]) of the table


def yaw_at(t):
    """The table's yaw [deg] at t, joined linearly (held before the first row)."""
    for (t0, a0), (t1, a1) in zip(ROWS, ROWS[1:]):
        if t0 <= t <= t1:
            return a0 + (a1 - a0) * (t - t0) / (t1 - t0)
    return ROWS[0][1] if t < ROWS[0][0] else ROWS[-1][1]


def turned(local, yaw_deg):
    """R_y(yaw) p: about +y (up), (x, z) -> (x cos + z sin, -x sin + z cos)."""
    c, s = math.cos(math.radians(yaw_deg)), math.sin(math.radians(yaw_deg))
    x, y, z = local
    return (x * c + z * s, y, -x * s + z * c)


def run(cablefilm, scene, out):
    done = subprocess.run([cablefilm, "run", str(scene), "--no-film", "--out", str(out)],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise SystemExit(f"FAIL: {scene.name}: exit {done.returncode}: {done.stderr[-600:]}")


def table(path):
    return list(csv.DictReader(io.StringIO(path.read_text())))


def variant(tmp, source, name, csv_text):
    """The scene with its table file replaced by `csv_text`."""
    (tmp / f"{name}.csv").write_text(csv_text)
    text = source.read_text().replace(f'file = "{SCENE}.csv"', f'file = "{name}.csv"')
    (tmp / f"{name}.toml").write_text(text)
    return tmp / f"{name}.toml"


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cablefilm", required=True)
    parser.add_argument("--source-dir", required=True, type=pathlib.Path)
    args = parser.parse_args()
    source = args.source_dir / "tests" / "scenes" / "system" / f"{SCENE}.toml"
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        shutil.copy(source, tmp / f"{SCENE}.toml")
        shutil.copy(source.with_suffix(".csv"), tmp / f"{SCENE}.csv")
        run(args.cablefilm, tmp / f"{SCENE}.toml", tmp / "yaw")
        points = table(tmp / "yaw" / "points.csv")
        worst = 0.0
        for r in points:
            if r["point"] not in LOCAL:
                continue
            want = turned(LOCAL[r["point"]], REST_YAW + yaw_at(float(r["t"])))
            worst = max(worst, *(abs(float(r[k]) - w) for k, w in zip("xyz", want)))
        rows = sum(r["point"] in LOCAL for r in points)
        print(f"{rows} fairlead rows, farthest from R(theta) p: {worst:.3g} m")
        if rows != 3 * 33 or not worst <= 1e-9:
            failures.append(f"fairleads: {rows} rows (99 expected), {worst:.3g} m from R p")
        body = table(tmp / "yaw" / "body.csv")
        worst_angle = max(abs(float(r["ry"]) - REST_YAW - yaw_at(float(r["t"]))) for r in body)
        worst_angle = max(worst_angle, *(abs(float(r[k])) for r in body for k in ("rx", "rz")))
        print(f"body.csv: {len(body)} rows, its angle at most {worst_angle:.3g} deg off the table's")
        if len(body) != 33 or not worst_angle <= 1e-8:
            failures.append(f"body.csv angles {worst_angle:.3g} deg off the table's")

        # The same platform still: a 4-column table, and a 7-column one whose angles are 0.
        still4 = variant(tmp, source, "still4", "t,x,y,z\n0,0,0,0\n1,0,0,0\n5,0,0,0\n10,0,0,0\n")
        still7 = variant(tmp, source, "still7", "t,x,y,z,rx,ry,rz\n0,0,0,0,0,0,0\n1,0,0,0,0,0,0\n"
                         "5,0,0,0,0,0,0\n10,0,0,0,0,0,0\n")
        run(args.cablefilm, still4, tmp / "still4")
        run(args.cablefilm, still7, tmp / "still7")
        for name in ["points.csv", "body.csv"] + [f"lines/leg{k}/timeseries.csv" for k in (1, 2, 3)]:
            if (tmp / "still4" / name).read_bytes() != (tmp / "still7" / name).read_bytes():
                failures.append(f"{name}: the 7-column table with no turn differs from the 4-column")
        # The yaw moves the fairleads (20 m x 4 degrees ~ 1.4 m) and so the legs' pull.
        still = table(tmp / "still4" / "points.csv")
        last = {r["point"]: r for r in points if float(r["t"]) == 8.0}
        last_still = {r["point"]: r for r in still if float(r["t"]) == 8.0}
        moved = math.dist(*([float(d["fairlead1"][k]) for k in "xyz"] for d in (last, last_still)))
        pull = max(abs(float(last[p][k]) - float(last_still[p][k]))
                   for p in LOCAL for k in ("fx", "fy", "fz"))
        scale = max(abs(float(last_still[p][k])) for p in LOCAL for k in ("fx", "fy", "fz"))
        print(f"at t = 8 s fairlead1 moved {moved:.4g} m by the yaw; the legs' pull changed by "
              f"up to {pull:.4g} N (of {scale:.4g} N)")
        expected = 2 * 20.0 * math.sin(math.radians(2.0))  # the chord of 4 degrees at 20 m
        if not abs(moved - expected) <= 1e-9:
            failures.append(f"fairlead1 moved {moved} m, not the 4-degree chord {expected} m")
        if not pull >= 1e-3 * scale:
            failures.append(f"the yaw changed the legs' pull by only {pull} N")
    for f in failures:
        print("FAIL:", f)
    print("FAIL" if failures else "ok")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
