#!/usr/bin/env python3
"""Issue 20: the Python module for scenes of several lines ([[line]], [[point]], [[body]])
against the command line it shares its code with: the same Result and Equilibrium as a single
line's, each line a Line. Run by ctest as module_test.py is (PYTHONPATH,
CABLEFILM_PROGRAM, CABLEFILM_SOURCE_DIR, CABLEFILM_TEST_TMP); one class per ctest test:
several_lines_test.py -v RunOfLines.

The truths are the program's files, which the rest of the suite checks: each line's
lines/<name>/results.nc (bit for bit), timeseries.csv and equilibrium.csv, points.csv and
body.csv (to the digits they print), the text `cablefilm check` and `cablefilm stiffness` print
and the CSV `cablefilm offset` writes; and the statics themselves: the stiffness's K_xx is the
offset curve's slope at the equilibrium, and a body at equilibrium carries its lines' load
against its own.
"""
import atexit
import csv
import os
import shutil
import subprocess
import tempfile
import unittest

import numpy as np
import netCDF4

import cablefilm

PROGRAM = os.environ["CABLEFILM_PROGRAM"]
SOURCE = os.environ["CABLEFILM_SOURCE_DIR"]
TMP = os.environ.get("CABLEFILM_TEST_TMP", tempfile.gettempdir())
PLATFORM = os.path.join(SOURCE, "scenes", "floating_platform.toml")
SPREAD = os.path.join(SOURCE, "scenes", "spread_mooring.toml")
P63 = os.path.join(SOURCE, "scenes", "polachek1963.toml")
# The keys of a Result's stats, the same for every scene (module_test.py checks a line's).
STATS_KEYS = {"integrator", "steps", "rejected", "newton_iterations", "snaps", "unresolved_snaps",
              "snap_windows", "explicit_steps", "equilibrium_iterations", "equilibrium_residual",
              "equilibrium_relaxed"}


def workdir(name):
    """A new folder under TMP, removed when the tests end (kept with CABLEFILM_KEEP_TEST_FILES)."""
    path = tempfile.mkdtemp(prefix=name + "_", dir=TMP)
    if not os.environ.get("CABLEFILM_KEEP_TEST_FILES"):
        atexit.register(shutil.rmtree, path, True)
    return path


def cli(*args):
    """Runs the program; returns (status, stdout, stderr)."""
    r = subprocess.run([PROGRAM, *args], stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                       text=True)
    return r.returncode, r.stdout, r.stderr


def shortened(source, seconds, name):
    """The scene cut to `seconds` of simulation, written to a file of its own: (Scene, path)."""
    scene = cablefilm.load(source)
    scene["simulation.duration"] = seconds
    out = workdir(name)
    path = os.path.join(out, "scene.toml")
    with open(path, "w") as f:
        f.write(scene.text)
    return scene, path, out


def run_cli(path, out):
    status, stdout, stderr = cli("run", path, "--no-film", "--out", out)
    if status != 0:
        raise AssertionError("cablefilm run failed (%d): %s%s" % (status, stdout, stderr))
    return stdout


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def g(fmt, values):
    return [fmt % v for v in values]


def assert_same_bits(test, a, b, what):
    a = np.ascontiguousarray(a, dtype=np.float64)
    b = np.ascontiguousarray(b, dtype=np.float64)
    test.assertEqual(a.shape, b.shape, what + ": shapes")
    differ = np.count_nonzero(a.view(np.uint64) != b.view(np.uint64))
    test.assertEqual(differ, 0, "%s: %d of %d doubles differ" % (what, differ, a.size))


class RunOfLines(unittest.TestCase):
    """cablefilm.run of several lines: every line's rows, the points and the body, as the files
    of `cablefilm run` hold them."""

    def check_against_cli(self, source, seconds, name):
        scene, path, out = shortened(source, seconds, name)
        self.assertGreater(len(scene.lines), 1)
        stdout = run_cli(path, out)
        r = cablefilm.run(scene)
        self.assertIsInstance(r, cablefilm.Result)
        self.assertTrue(r.completed)
        self.assertEqual(set(r.stats), STATS_KEYS)
        self.assertEqual(list(r.lines), scene.lines)
        self.assertEqual(r.line_names, scene.lines)
        self.assertEqual(r.point_names, scene.points)
        self.assertEqual(r.body_names, scene.bodies)
        n = r.time.shape[0]
        self.assertEqual(r.time[-1], seconds)
        for name, line in r.lines.items():
            self.assertIsInstance(line, cablefilm.Line)
            self.assertEqual(line.name, name)
            self.assertEqual(set(line.stats), STATS_KEYS)
            assert_same_bits(self, line.time, r.time, name + ": time")
            with netCDF4.Dataset(os.path.join(out, "lines", name, "results.nc")) as ds:
                for v in ["time", "x", "y", "z", "tension", "x_start", "y_start", "z_start",
                          "x_end", "y_end", "z_end", "s", "s_link"]:
                    assert_same_bits(self, getattr(line, v), ds.variables[v][:].data,
                                     name + ": " + v)
            rows = read_csv(os.path.join(out, "lines", name, "timeseries.csv"))
            self.assertEqual(len(rows), n)
            self.assertEqual([row["t"] for row in rows], g("%.10g", r.time))
            for col, ours in [("x_end", line.x_end), ("y_end", line.y_end),
                              ("z_end", line.z_end)]:
                self.assertEqual([row[col] for row in rows], g("%.12g", ours), name + ": " + col)
            for col, ours in [("tension_start", line.tension[:, 0]),
                              ("tension_end", line.tension[:, -1]),
                              ("tension_max", line.tension.max(axis=1))]:
                self.assertEqual([row[col] for row in rows], g("%.10g", ours), name + ": " + col)
            self.assertEqual(line.position.shape, (n, scene.stations[name], 3))
            self.assertEqual(line.tension.shape, (n, scene.links[name]))
        # points.csv: a row per point per output time.
        rows = read_csv(os.path.join(out, "points.csv"))
        npts = len(r.point_names)
        self.assertEqual(r.point_position.shape, (n, npts, 3))
        self.assertEqual(r.point_force.shape, (n, npts, 3))
        self.assertEqual(len(rows), n * npts)
        self.assertEqual([row["t"] for row in rows], g("%.10g", np.repeat(r.time, npts)))
        self.assertEqual([row["point"] for row in rows], r.point_names * n)
        for k, col in enumerate("xyz"):
            self.assertEqual([row[col] for row in rows],
                             g("%.12g", r.point_position[:, :, k].ravel()), col)
            self.assertEqual([row["f" + col] for row in rows],
                             g("%.10g", r.point_force[:, :, k].ravel()), "f" + col)
        # The peak the run printed: its tension, time, line and link.
        self.assertIn("peak tension %.6g N at t = %.4g s in line \"%s\", link %d"
                      % (r.peak_tension, r.peak_time, r.peak_line, r.peak_link), stdout)
        self.assertEqual(r.peak_tension, max(l.tension.max() for l in r.lines.values()))
        self.assertEqual(r.peak_tension, r.lines[r.peak_line].tension.max())
        self.assertEqual(r.peak_tension, r.lines[r.peak_line].peak_tension)
        # A line's arrays are its Line's alone: the Result of several lines has none, and says
        # where they are.
        for attribute in ("x", "tension", "load_start", "s"):
            self.assertFalse(hasattr(r, attribute), attribute)
        with self.assertRaisesRegex(AttributeError, r"r\.lines\[name\]\.tension"):
            r.tension
        return r, out

    def test_spread_mooring(self):
        # Moved fairleads and a clump weight shared by two lines; no body.
        r, _ = self.check_against_cli(SPREAD, 10.0, "spread")
        self.assertEqual(r.body_pose.shape, (r.time.shape[0], 0, 6))
        # The clump weight joins leg1's two lines: both end there, where the point is.
        clump = r.point_names.index("clump")
        assert_same_bits(self, r.lines["leg1_lower"].position[:, -1], r.point_position[:, clump],
                         "leg1_lower's end at the clump")
        # Its statics reached from the scene's guess: no damped motion needed.
        self.assertEqual(r.stats["equilibrium_relaxed"], 0.0)

    def test_floating_platform(self):
        # A free body let go from an offset: body.csv's pose (degrees there) and load.
        r, out = self.check_against_cli(PLATFORM, 5.0, "platform")
        n = r.time.shape[0]
        self.assertEqual(r.body_pose.shape, (n, 1, 6))
        rows = read_csv(os.path.join(out, "body.csv"))
        self.assertEqual(len(rows), n)
        self.assertEqual([row["body"] for row in rows], ["platform"] * n)
        for k, col in enumerate(["x", "y", "z"]):
            self.assertEqual([row[col] for row in rows], g("%.12g", r.body_pose[:, 0, k]), col)
        for k, col in enumerate(["rx", "ry", "rz"]):
            self.assertEqual([row[col] for row in rows],
                             g("%.10g", r.body_pose[:, 0, 3 + k] * (180.0 / np.pi)), col)
        for k, col in enumerate(["fx", "fy", "fz", "mx", "my", "mz"]):
            self.assertEqual([row[col] for row in rows], g("%.10g", r.body_load[:, 0, k]), col)
        # The initial offset: 3 degrees of roll at t = 0, in radians here.
        self.assertAlmostEqual(r.body_pose[0, 0, 3], np.radians(3.0), places=12)

    def test_arrays_outlive_the_result(self):
        # The views keep the run alive; they are read-only.
        r = cablefilm.run(shortened(SPREAD, 1.0, "views")[0])
        line = r.lines["leg2"]
        force = r.point_force
        del r
        self.assertEqual(line.tension.shape[0], force.shape[0])
        self.assertFalse(force.flags.writeable)
        with self.assertRaises(ValueError):
            force[0, 0, 0] = 1.0


class EquilibriumOfLines(unittest.TestCase):
    """cablefilm.equilibrium of several lines: each line's equilibrium.csv, and the first row of
    points.csv and body.csv with the body at its equilibrium (no initial offset)."""

    def test_spread_mooring(self):
        scene, path, out = shortened(SPREAD, 0.5, "spread_eq")
        run_cli(path, out)
        e = cablefilm.equilibrium(scene)
        self.assertIsInstance(e, cablefilm.Equilibrium)
        self.assertEqual(list(e.lines), scene.lines)
        self.assertFalse(hasattr(e, "tension"))
        with self.assertRaises(TypeError):
            x, y, tension = e   # a line's equilibrium unpacks; several lines' do not
        for name, line in e.lines.items():
            rows = read_csv(os.path.join(out, "lines", name, "equilibrium.csv"))
            for col, ours in [("x", line.x), ("y", line.y), ("z", line.z)]:
                self.assertEqual([row[col] for row in rows], g("%.12g", ours), name + ": " + col)
            self.assertEqual([row["tension"] for row in rows[:-1]], g("%.10g", line.tension))
            assert_same_bits(self, line.position[:, 1], line.y, name + ": position")
        rows = read_csv(os.path.join(out, "points.csv"))[:len(e.point_names)]
        self.assertEqual([row["point"] for row in rows], e.point_names)
        for k, col in enumerate("xyz"):
            self.assertEqual([row[col] for row in rows], g("%.12g", e.point_position[:, k]))
            self.assertEqual([row["f" + col] for row in rows], g("%.10g", e.point_force[:, k]))
        # The clump weight rests on the bed (y = -100 m), where the pull of its two lines is
        # that of their end links along them (worked out here from their shapes), and nearly
        # balanced (the bed carries its weight).
        clump = e.point_names.index("clump")
        self.assertAlmostEqual(e.point_position[clump, 1], -100.0, places=2)
        lower, upper = e.lines["leg1_lower"], e.lines["leg1_upper"]
        t_lower = lower.position[-1] - lower.position[-2]
        t_upper = upper.position[1] - upper.position[0]
        pull = (upper.tension[0] * t_upper / np.linalg.norm(t_upper)
                - lower.tension[-1] * t_lower / np.linalg.norm(t_lower))
        self.assertLess(np.abs(pull - e.point_force[clump]).max(), 1e-6 * upper.tension[0])
        self.assertLess(np.abs(e.point_force[clump]).max(), 1e-3 * upper.tension[0])

    def test_platform_without_offset(self):
        # The equilibrium ignores the initial offset: the run of the same scene with none
        # starts there.
        scene = cablefilm.load(PLATFORM)
        e = cablefilm.equilibrium(scene)
        scene["body[0].initial_offset"] = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0]
        scene["simulation.duration"] = 0.5
        r = cablefilm.run(scene)
        assert_same_bits(self, e.body_pose, r.body_pose[0], "body pose")
        assert_same_bits(self, e.body_load, r.body_load[0], "body load")
        assert_same_bits(self, e.point_force, r.point_force[0], "point forces")
        for name in scene.lines:
            assert_same_bits(self, e.lines[name].tension, r.lines[name].tension[0], name)
        # At equilibrium the lines' horizontal pull balances the 200 kN wind.
        self.assertAlmostEqual(e.body_load[0, 0] / -2.0e5, 1.0, places=4)
        # Its statics are the model's Newton on the free body, as `cablefilm check` prints them,
        # and the run's stats say the same.
        status, stdout, stderr = cli("check", PLATFORM)
        self.assertEqual(status, 0, stderr)
        self.assertIn("equilibrium: %d Newton iteration(s) on the shared points and free bodies, "
                      "out-of-balance %.3g N" % (e.iterations, e.residual), stdout)
        self.assertGreater(e.iterations, 0)
        self.assertFalse(e.fallback)
        self.assertEqual((r.stats["equilibrium_iterations"], r.stats["equilibrium_residual"]),
                         (e.iterations, e.residual))


ABOVE_ANCHOR = os.path.join(SOURCE, "tests", "scenes", "moordyn", "body_above_anchor.txt")


def cli_stiffness(path):
    status, stdout, stderr = cli("stiffness", path)
    if status != 0:
        raise AssertionError("cablefilm stiffness failed: " + stdout + stderr)
    lines = stdout.splitlines()
    pose_line = next(l for l in lines if l.startswith("pose at equilibrium"))
    K = np.array([[float(v) for v in l.split()] for l in lines[-6:]])
    return pose_line, K


class BodyTools(unittest.TestCase):
    """cablefilm.stiffness and offset_curve: what `cablefilm stiffness` prints and `cablefilm
    offset` writes, and K_xx the slope of the offset curve."""

    def test_stiffness_is_the_commands(self):
        pose, K = cablefilm.stiffness(PLATFORM)
        self.assertEqual(K.shape, (6, 6))
        pose_line, K_cli = cli_stiffness(PLATFORM)
        deg = 180.0 / np.pi
        self.assertEqual(pose_line,
                         "pose at equilibrium: x %.6g m, y %.6g m, z %.6g m, about x %.6g deg, "
                         "about y %.6g deg, about z %.6g deg"
                         % (pose[0], pose[1], pose[2], pose[3] * deg, pose[4] * deg,
                            pose[5] * deg))
        self.assertEqual([["%.6e" % v for v in row] for row in K],
                         [["%.6e" % v for v in row] for row in K_cli])
        # The same pose as the equilibrium's body.
        e = cablefilm.equilibrium(PLATFORM)
        self.assertTrue(np.allclose(pose, e.body_pose[0], rtol=0, atol=1e-9))
        self.assertEqual(cablefilm.stiffness(PLATFORM, body="platform")[1].tolist(), K.tolist())

    def test_offset_curve_is_the_commands(self):
        for heading in (0.0, 30.0):
            status, stdout, stderr = cli("offset", PLATFORM, "--heading", "%g" % heading)
            self.assertEqual(status, 0, stderr)
            rows = list(csv.DictReader(stdout.splitlines()))
            c = cablefilm.offset_curve(PLATFORM, heading=heading)
            self.assertEqual(c["body"], "platform")
            self.assertEqual(c["load"].shape, (11, 6))
            self.assertEqual(sorted(c["tension"]), ["leg1", "leg2", "leg3"])
            self.assertEqual([r["offset"] for r in rows], g("%.10g", c["offset"]))
            self.assertEqual([r["restoring"] for r in rows], g("%.10g", c["restoring"]))
            for k, col in enumerate(["fx", "fy", "fz", "mx", "my", "mz"]):
                self.assertEqual([r[col] for r in rows], g("%.10g", c["load"][:, k]), col)
            for name, t in c["tension"].items():
                self.assertEqual([r["tension_" + name] for r in rows], g("%.10g", t), name)

    def test_relaxed_equilibrium_is_the_commands(self):
        # A MoorDyn file whose free body is given above the anchor it hangs below (Newton from
        # there fails; the statics' relaxation finds it): the same pose and stiffness as the
        # command's, the body where the hand value puts it (tests/app/cli_test.cpp: 4 (1 +
        # 273.45 / 2000) m below the anchor at y = -5 m).
        path = ABOVE_ANCHOR
        pose, K = cablefilm.stiffness(path)
        pose_line, K_cli = cli_stiffness(path)
        self.assertIn("y %.6g m," % pose[1], pose_line)
        self.assertEqual([["%.6e" % v for v in row] for row in K],
                         [["%.6e" % v for v in row] for row in K_cli])
        T = (20 - 1025 * 0.004) * 9.81 + 2 * (8 - 1025 * np.pi * 0.05 ** 2 / 4) * 9.81
        # Statics to 1e-9 of the load: 1e-8 m.
        self.assertAlmostEqual(pose[1], -5 - 4 * (1 + T / 2000), delta=1e-8)
        c = cablefilm.offset_curve(path, offsets=[0.0])
        self.assertAlmostEqual(c["restoring"][0], 0.0, delta=1e-9)
        # One line, but on a free body: its statics are the model's (Newton on the body after
        # the relaxation), as `cablefilm check` prints them, not the held line's own solve.
        e = cablefilm.equilibrium(path)
        self.assertEqual(list(e.lines), ["1"])
        status, stdout, stderr = cli("check", path)
        self.assertEqual(status, 0, stderr)
        self.assertIn("equilibrium: %d Newton iteration(s) on the shared points and free bodies, "
                      "out-of-balance %.3g N" % (e.iterations, e.residual), stdout)
        self.assertIn("not reached from the scene's positions", stdout)
        self.assertTrue(e.fallback)
        self.assertAlmostEqual(e.body_pose[0, 1], pose[1], delta=1e-8)

    def test_stiffness_is_the_curves_slope(self):
        # K_xx = -dFx/dx by central differences of h = 1e-4 of the shortest line (52 m); the
        # offset curve at -h and +h along x gives the same difference of the restoring force.
        pose, K = cablefilm.stiffness(PLATFORM)
        h = 1e-4 * 520.0
        c = cablefilm.offset_curve(PLATFORM, heading=0.0, offsets=[-h, h])
        slope = (c["restoring"][1] - c["restoring"][0]) / (2 * h)
        self.assertAlmostEqual(slope / K[0, 0], 1.0, places=6)
        # Along z (heading 90 degrees: +z), K_zz.
        c = cablefilm.offset_curve(PLATFORM, heading=90.0, offsets=[-h, h])
        slope = (c["restoring"][1] - c["restoring"][0]) / (2 * h)
        self.assertAlmostEqual(slope / K[2, 2], 1.0, places=6)
        # The moorings' translational stiffness is symmetric (a potential), to the
        # differences' truncation.
        T = K[:3, :3]
        self.assertLess(np.abs(T - T.T).max(), 1e-3 * np.abs(T).max())

    def test_errors_name_the_body(self):
        with self.assertRaisesRegex(ValueError, 'no body is named "raft".*"platform"'):
            cablefilm.stiffness(PLATFORM, body="raft")
        with self.assertRaisesRegex(ValueError, "no \\[\\[body\\]\\]"):
            cablefilm.offset_curve(SPREAD)
        # A scene with no body, of one line or several: a ValueError, not a SceneError (the
        # scene is good; the tool has nothing to move).
        for path in (P63, SPREAD):
            with self.assertRaisesRegex(ValueError, "no \\[\\[body\\]\\]") as caught:
                cablefilm.stiffness(path)
            self.assertNotIsInstance(caught.exception, cablefilm.SceneError)
        with self.assertRaisesRegex(ValueError, "offsets"):
            cablefilm.offset_curve(PLATFORM, offsets=[float("nan")])

    def test_heading_is_checked_as_the_commands(self):
        # 1e308 degrees gave NaN loads; the command line refuses beyond a turn: one check, the
        # offset curve's own.
        for heading in (1e308, -361.0, float("nan")):
            with self.assertRaisesRegex(ValueError,
                                        "heading: expected an angle from -360 to 360 degrees"):
                cablefilm.offset_curve(PLATFORM, heading=heading, offsets=[0.0])
        status, _, stderr = cli("offset", PLATFORM, "--heading", "1e308")
        self.assertEqual(status, 2)
        self.assertIn("--heading: expected a number from -360 to 360 degrees", stderr)


class ScenesOfLines(unittest.TestCase):
    """The Scene of several lines: its names, its keys read and set as a line's are, clear
    errors."""

    def test_names_and_keys(self):
        scene = cablefilm.load(PLATFORM)
        self.assertFalse(hasattr(scene, "is_system"))
        self.assertEqual(scene.lines, ["leg1", "leg2", "leg3"])
        self.assertEqual(scene.points, ["anchor1", "anchor2", "anchor3", "fairlead1",
                                        "fairlead2", "fairlead3"])
        self.assertEqual(scene.bodies, ["platform"])
        self.assertEqual(scene.links, {"leg1": 52, "leg2": 52, "leg3": 52})
        self.assertEqual(scene.stations, {"leg1": 53, "leg2": 53, "leg3": 53})
        self.assertIn("3 lines, 6 points, 1 body", repr(scene))
        self.assertEqual(scene["body[0].force"], [2.0e5, 0.0, 0.0])
        self.assertEqual(scene["point[3].position"], [20.0, -10.0, 0.0])
        scene["body[0].force"] = [1.0e5, 0.0, 0.0]
        self.assertEqual(scene["body[0].force"], [1.0e5, 0.0, 0.0])
        scene["line[0].section[0].segments"] = 40
        self.assertEqual(scene.links["leg1"], 40)
        e = cablefilm.equilibrium(scene)
        self.assertEqual(e.lines["leg1"].tension.shape, (40,))
        self.assertAlmostEqual(e.body_load[0, 0] / -1.0e5, 1.0, places=4)
        # A [cable] scene is one line, "cable", between the points "start" and "end".
        single = cablefilm.load(P63)
        self.assertEqual((single.lines, single.points, single.bodies),
                         (["cable"], ["start", "end"], []))
        self.assertEqual((single.stations, single.links), (61, 60))

    def test_bad_values_are_refused(self):
        scene = cablefilm.load(PLATFORM)
        text = scene.text
        with self.assertRaisesRegex(cablefilm.SceneError, "mass"):
            scene["body[0].mass"] = -1.0
        with self.assertRaisesRegex(cablefilm.SceneError, "body\\[3\\]"):
            scene["body[3].mass"] = 1.0
        with self.assertRaises(KeyError):
            scene["point[9].position"]
        self.assertEqual(scene.text, text)

    def test_sweep_of_a_system(self):
        scene = shortened(SPREAD, 1.0, "sweep")[0]
        rows = cablefilm.sweep(scene, {"point[6].mass": [4000.0, 6000.0]}, jobs=2,
                               keep_results=True)
        self.assertEqual([row["status"] for row in rows], ["ok", "ok"])
        for row, mass in zip(rows, [4000.0, 6000.0]):
            alone = scene.copy()
            alone["point[6].mass"] = mass
            r = cablefilm.run(alone)
            self.assertEqual(row["peak_tension"], r.peak_tension)
            self.assertIsInstance(row["result"], cablefilm.Result)
            assert_same_bits(self, row["result"].point_force, r.point_force, "point forces")

    def test_ctrl_c_stops_a_run(self):
        # SIGINT while the GIL is released: the run stops within a step, KeyboardInterrupt.
        import signal
        import threading
        import time
        # An hour of simulation (some 20 s of work on a quiet machine, far more than the 0.3 s
        # before the signal: the scene's own 60 s now run in about 0.3 s, and a signal that
        # came after the run would interrupt the next test instead).
        scene = cablefilm.load(SPREAD)
        scene["simulation.duration"] = 3600.0
        timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
        start = time.monotonic()
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt):
                cablefilm.run(scene)
            self.assertLess(time.monotonic() - start, 1.5)
        finally:
            timer.cancel()
            timer.join()

    @unittest.skipUnless(hasattr(cablefilm, "render_film"), "built without the renderer")
    def test_pictures(self):
        # A frame is pixel for pixel the film's (cablefilm run --frames): the platform's rows
        # are 0.1 s apart, at 10 frames a second a row a frame, frame 10 is t = 1 s.
        from module_test import read_png
        scene, path, out = shortened(PLATFORM, 2.0, "frames")
        status, stdout, stderr = cli("run", path, "--frames", "--size", "320x180", "--fps", "10",
                                     "--out", out)
        self.assertEqual(status, 0, stdout + stderr)
        r = cablefilm.run(scene)
        frame = cablefilm.render_frame(r, 1.0, width=320, height=180)
        self.assertEqual(frame.shape, (180, 320, 3))
        self.assertGreater(len(np.unique(frame.reshape(-1, 3), axis=0)), 100)
        png = read_png(os.path.join(out, "frames", "frame_%06d.png" % 10))[:, :, :3]
        differ = np.count_nonzero(np.any(png != frame, axis=2))
        self.assertEqual(differ, 0, "%d pixels differ from the film's frame 10" % differ)
        self.assertTrue(np.any(cablefilm.render_frame(r, row=0, width=320, height=180) != frame))
        # A Line is not a run: its ends move with the others, drawn with the Result; the film
        # is an MP4.
        with self.assertRaisesRegex(TypeError, "Result"):
            cablefilm.render_frame(r.lines["leg2"])
        with self.assertRaisesRegex(TypeError, "Result"):
            cablefilm.render_film(r.lines["leg2"], os.path.join(workdir("film"), "leg2.mp4"))
        film_dir = workdir("film")
        path = cablefilm.render_film(r, os.path.join(film_dir, "platform.mp4"), width=320,
                                     height=180)
        with open(path, "rb") as f:
            self.assertEqual(f.read(12)[4:8], b"ftyp")
        self.assertEqual(os.listdir(film_dir), ["platform.mp4"])


if __name__ == "__main__":
    unittest.main()
