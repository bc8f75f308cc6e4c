"""A driven body that turns (issue 20), end to end: tests/scenes/system/turning_platform.toml,
a platform yawed 4 degrees by a 7-column table (t, x, y, z, rx, ry, rz; joined linearly, so its
angle at any time is known by hand). Checks that
- every fairlead in points.csv is where the turn puts it, R(theta(t)) p with theta the rest
  orientation plus the table's angle at t, to 1e-9 m (points.csv prints 12 digits: 1e-10 m at
  these 20 m; the step puts a prescribed end exactly at its motion), and body.csv's ry column is
  that angle (to 1e-8 degrees: it prints 10 digits of 10 to 14 degrees, rounding by up to
  5e-9);
- the yaw moves the fairleads and changes the legs' pull on them (against the same run with the
  body still);
- a table without angles (four columns) and one with angle columns of zeros give the same
  results to the byte: a table with no turn is the old motion;
- the same for eq. (3) turning the platform (rx_amplitudes, ry_amplitudes, by hand) and for a
  splined 7-column table turning it about all three axes (a natural spline solved here);
- the loads at the turning fairleads (which take their accelerations) are those of fairleads
  moved by tables of the same paths (same_paths_as_tables)."""
import argparse
import math
import pathlib
import shutil
import sys
import tempfile

from scene_runs import report, run, table

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


def rotation(angles_deg):
    """R = Rz Ry Rx (body.h: about x, then y, then z, fixed axes) as rows."""
    ax, ay, az = (math.radians(a) for a in angles_deg)
    cx, sx, cy, sy, cz, sz = (math.cos(ax), math.sin(ax), math.cos(ay), math.sin(ay),
                              math.cos(az), math.sin(az))
    Rx = ((1, 0, 0), (0, cx, -sx), (0, sx, cx))
    Ry = ((cy, 0, sy), (0, 1, 0), (-sy, 0, cy))
    Rz = ((cz, -sz, 0), (sz, cz, 0), (0, 0, 1))
    mul = lambda A, B: tuple(tuple(sum(A[i][k] * B[k][j] for k in range(3)) for j in range(3))
                             for i in range(3))
    return mul(Rz, mul(Ry, Rx))


def natural_spline(ts, ys):
    """The natural cubic spline through (ts, ys) as a function of t (held outside), solved
    here as a dense linear system for the second derivatives (zero at both ends)."""
    n = len(ts)
    A = [[0.0] * n for _ in range(n)]
    b = [0.0] * n
    A[0][0] = A[-1][-1] = 1.0
    for i in range(1, n - 1):
        h0, h1 = ts[i] - ts[i - 1], ts[i + 1] - ts[i]
        A[i][i - 1], A[i][i], A[i][i + 1] = h0, 2 * (h0 + h1), h1
        b[i] = 6 * ((ys[i + 1] - ys[i]) / h1 - (ys[i] - ys[i - 1]) / h0)
    for c in range(n):  # Gaussian elimination (the system is diagonally dominant)
        for r in range(c + 1, n):
            f = A[r][c] / A[c][c]
            for k in range(c, n):
                A[r][k] -= f * A[c][k]
            b[r] -= f * b[c]
    m = [0.0] * n
    for r in range(n - 1, -1, -1):
        m[r] = (b[r] - sum(A[r][k] * m[k] for k in range(r + 1, n))) / A[r][r]

    def at(t):
        if t <= ts[0]:
            return ys[0]
        if t >= ts[-1]:
            return ys[-1]
        i = max(k for k in range(n - 1) if ts[k] <= t)
        h = ts[i + 1] - ts[i]
        a, bb = (ts[i + 1] - t) / h, (t - ts[i]) / h
        return (a * ys[i] + bb * ys[i + 1] +
                ((a ** 3 - a) * m[i] + (bb ** 3 - bb) * m[i + 1]) * h * h / 6)
    return at


def check_poses(out, pose, label):
    """Every fairlead in points.csv at r + R(theta) p and body.csv's pose, `pose(t)` giving
    (r [m], theta [deg]). Bounds as the module's docstring says."""
    failures = []
    worst = 0.0
    points = table(out / "points.csv")
    for r in points:
        if r["point"] not in LOCAL:
            continue
        ref, angles = pose(float(r["t"]))
        R = rotation(angles)
        want = [ref[i] + sum(R[i][k] * LOCAL[r["point"]][k] for k in range(3)) for i in range(3)]
        worst = max(worst, *(abs(float(r[k]) - w) for k, w in zip("xyz", want)))
    worst_angle = 0.0
    for r in table(out / "body.csv"):
        ref, angles = pose(float(r["t"]))
        worst_angle = max(worst_angle, *(abs(float(r[k]) - a) for k, a in zip(("rx", "ry", "rz"), angles)))
    print(f"{label}: fairleads at most {worst:.3g} m from r + R(theta) p, body.csv's angles "
          f"{worst_angle:.3g} deg from theta")
    if not worst <= 1e-9:
        failures.append(f"{label}: a fairlead {worst:.3g} m from r + R(theta) p")
    if not worst_angle <= 1e-8:
        failures.append(f"{label}: body.csv's angles {worst_angle:.3g} deg off")
    return failures


def same_paths_as_tables(args, tmp, scene, pose):
    """The turning body's velocity and acceleration, through the whole step: the same scene
    with the body gone and each fairlead a point moved by a table of its path r + R(theta) p
    sampled here every 5 ms (splined), both at a fixed step of 10 ms (the same steps). The
    fairleads' loads in points.csv (their end stations' force less their inertia, m a: 225 kg
    each) must agree to 1e-6 of the largest: the spline's own error in acceleration, h^2/12
    |x| ~ 2e-6 m/s^2 at h = 5 ms (|x| ~ 20 m x (1 rad/s)^4 x 0.05 rad), is 5e-4 N
    there, 2e-8 of the 3e4 N loads; the measured difference is 3e-3 N (8e-8). Leaving out only
    the centripetal part of R'' (the rates squared) puts them 13 N apart (tried: 4e-4)."""
    fixed = scene.replace("[simulation]\nduration = 8.0", "[simulation]\nduration = 8.0\ntime_step = 0.01")
    (tmp / "turn_fixed.toml").write_text(fixed)
    tables = fixed[:fixed.index("[[body]]")] + fixed[fixed.index("[[point]]"):]
    dt = 0.005
    for name, p in LOCAL.items():
        rows = ["t,x,y,z"]
        for i in range(int(round(9.0 / dt)) + 1):
            r, angles = pose(i * dt)
            R = rotation(angles)
            x = [r[k] + sum(R[k][j] * p[j] for j in range(3)) for k in range(3)]
            rows.append(f"{i * dt:.6f},{x[0]:.17g},{x[1]:.17g},{x[2]:.17g}")
        (tmp / f"{name}.csv").write_text("\n".join(rows) + "\n")
        placed = f'name = "{name}"\nbody = "platform"\nposition = [{p[0]}, {p[1]}, {p[2]}]'
        if placed not in tables:
            return [f"same_paths_as_tables: no {placed!r} in the scene"]
        tables = tables.replace(placed, f'name = "{name}"\nposition = [0.0, 0.0, 0.0]\n'
                                f'motion = "table"\nfile = "{name}.csv"')
    (tmp / "turn_tables.toml").write_text(tables)
    run(args.cablefilm, tmp / "turn_fixed.toml", tmp / "turn_fixed")
    run(args.cablefilm, tmp / "turn_tables.toml", tmp / "turn_tables")
    a = {(r["t"], r["point"]): r for r in table(tmp / "turn_fixed" / "points.csv")}
    b = {(r["t"], r["point"]): r for r in table(tmp / "turn_tables" / "points.csv")}
    keys = [k for k in a if k[1] in LOCAL]
    if len(keys) != 99 or any(k not in b for k in keys):
        return [f"turning body and tables: {len(keys)} fairlead rows, or rows missing"]
    loads = ("fx", "fy", "fz")
    worst = max(abs(float(a[k][c]) - float(b[k][c])) for k in keys for c in loads)
    largest = max(abs(float(a[k][c])) for k in keys for c in loads)
    print(f"turning body against its points' paths as tables: loads {worst:.3g} N apart "
          f"(of {largest:.4g} N)")
    if not worst <= 1e-6 * largest:
        return [f"turning body and tables: loads {worst:.3g} N apart, more than 1e-6 of {largest:.4g} N"]
    return []


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
        # Eq. (3) turning it too: surge 1 m and turns about x and y, ramped; by hand.
        troch = (tmp / f"{SCENE}.toml").read_text().replace(
            f'motion = "table"\nfile = "{SCENE}.csv"\ninterpolation = "linear"',
            'motion = "trochoid"\nx_amplitudes = [1.0, 0.0]\nrx_amplitudes = [0.5, 0.0]\n'
            'ry_amplitudes = [0.0, 3.0]\nperiod = 6.0\nramp_rate = 0.8')
        (tmp / "troch.toml").write_text(troch)
        run(args.cablefilm, tmp / "troch.toml", tmp / "troch")
        w, nu = 2 * math.pi / 6.0, 0.8

        def troch_pose(t):
            ramp = 1 - (1 + nu * t) * math.exp(-nu * t) if t > 0 else 0.0
            c, s = math.cos(w * t), math.sin(w * t)
            return (ramp * c, 0.0, 0.0), (0.5 * ramp * c, REST_YAW + 3.0 * ramp * s, 0.0)
        failures += check_poses(tmp / "troch", troch_pose, "trochoid")

        # A splined table turning about all three axes, against a natural spline solved here.
        ts = [0.0, 1.0, 3.0, 4.5, 7.0, 10.0]
        turns = [(0, 0, 0), (0, 0, 0), (1.0, 3.0, -0.5), (-0.5, 4.0, 0.8), (0.2, 2.0, 0.0),
                 (0.0, 2.0, 0.0)]
        rows = "".join(f"{t},0,0,0,{a},{b},{c}\n" for t, (a, b, c) in zip(ts, turns))
        spline = variant(tmp, source, "spline", "t,x,y,z,rx,ry,rz\n" + rows)
        spline.write_text(spline.read_text().replace('interpolation = "linear"\n', ""))
        run(args.cablefilm, spline, tmp / "spline")
        splines = [natural_spline(ts, [row[k] for row in turns]) for k in range(3)]

        def spline_pose(t):
            return (0.0, 0.0, 0.0), (splines[0](t), REST_YAW + splines[1](t), splines[2](t))
        failures += check_poses(tmp / "spline", spline_pose, "spline table")
        failures += same_paths_as_tables(args, tmp, troch, troch_pose)
    return report(failures)


if __name__ == "__main__":
    sys.exit(main())
