#!/usr/bin/env python3
"""Issue 12 part 4: the Python module `cablefilm` against the command line it shares its code
with, for scenes of one line ([cable] and [ends]; several_lines_test.py has those of several). Run by
ctest with Debian's Python and PYTHONPATH=<build>/python; CABLEFILM_PROGRAM is the build's
`cablefilm`, CABLEFILM_SOURCE_DIR the source tree, CABLEFILM_TEST_TMP a folder for what the
tests write. One class per ctest test: module_test.py -v ReproducesTheCli.

The truths are independent of the module: the program's own results.nc (read with netCDF4),
sweep.csv and `cablefilm check` messages, and a static balance of forces worked out here from
the scene's numbers.
"""
import atexit
import csv
import math
import os
import shutil
import struct
import subprocess
import tempfile
import threading
import tomllib
import unittest
import zlib

import numpy as np
import netCDF4

import cablefilm

PROGRAM = os.environ["CABLEFILM_PROGRAM"]
SOURCE = os.environ["CABLEFILM_SOURCE_DIR"]
TMP = os.environ.get("CABLEFILM_TEST_TMP", tempfile.gettempdir())
P63 = os.path.join(SOURCE, "scenes", "polachek1963.toml")


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


def bits(a):
    """The doubles' bit patterns: equal means equal to the bit (-0.0 and NaNs too)."""
    return np.ascontiguousarray(a, dtype=np.float64).view(np.uint64)


def assert_same_bits(test, a, b, what):
    a, b = np.asarray(a), np.asarray(b)
    test.assertEqual(a.shape, b.shape, what + ": shapes")
    differ = np.count_nonzero(bits(a) != bits(b))
    test.assertEqual(differ, 0, "%s: %d of %d doubles differ (largest difference %g)"
                     % (what, differ, a.size, np.max(np.abs(a - b)) if a.size else 0))


# The keys of a Result's stats, the same for every scene (several_lines_test.py checks one of several lines).
STATS_KEYS = {"integrator", "steps", "rejected", "newton_iterations", "snaps", "unresolved_snaps",
              "snap_windows", "explicit_steps", "equilibrium_iterations", "equilibrium_residual",
              "equilibrium_relaxed"}


def cli_results(scene_path, out):
    status, stdout, stderr = cli("run", scene_path, "--no-film", "--out", out)
    if status != 0:
        raise AssertionError("cablefilm run failed (%d): %s%s" % (status, stdout, stderr))
    return netCDF4.Dataset(os.path.join(out, "results.nc"))


def assert_result_is_file(test, result, ds):
    """Every variable of results.nc, bit for bit, against the module's arrays."""
    test.assertEqual(ds.dimensions["time"].size, result.time.shape[0])
    for name in ["time", "x", "y", "z", "tension", "x_start", "y_start", "z_start", "x_end",
                 "y_end", "z_end", "s", "s_link"]:
        assert_same_bits(test, getattr(result, name), ds.variables[name][:].data, name)


class ReproducesTheCli(unittest.TestCase):
    """Case P63 from the module and from `cablefilm run`: the same doubles."""

    def test_p63_bit_for_bit(self):
        with cli_results(P63, workdir("p63_cli")) as ds:
            result = cablefilm.run(cablefilm.load(P63))
            self.assertEqual(result.x.shape, (1801, 61))   # 60 s, a row every 1/30 s; 60 links
            self.assertEqual(result.tension.shape, (1801, 60))
            assert_result_is_file(self, result, ds)
            eq = cablefilm.equilibrium(P63)   # the initial state, solved on its own
            for name, ours in [("x_equilibrium", eq.x), ("y_equilibrium", eq.y),
                               ("z_equilibrium", eq.z), ("tension_equilibrium", eq.tension)]:
                assert_same_bits(self, ours, ds.variables[name][:].data, name)
            x, y, tension = eq   # unpacks so
            assert_same_bits(self, x, result.x[0], "equilibrium = first row")
            # P63 is in the x-y plane: z is 0 everywhere, exactly.
            self.assertEqual(result.z.shape, (1801, 61))
            self.assertEqual(result.position.shape, (1801, 61, 3))
            self.assertEqual(eq.position.shape, (61, 3))
            for z in (result.z, result.z_start, result.z_end, eq.z):
                self.assertEqual(np.count_nonzero(z), 0)
            # The run's printed peak: the largest tension_max of the rows.
            self.assertEqual(result.peak_tension, ds.variables["tension"][:].data.max())
            self.assertTrue(result.completed)
            self.assertEqual(result.warnings, [])
            # One Result for every scene: this one's single line is lines["cable"], whose
            # arrays are the Result's own (views of the same rows, so results.nc's doubles too).
            self.assertIsInstance(result, cablefilm.Result)
            self.assertEqual(list(result.lines), ["cable"])
            self.assertEqual(result.line_names, ["cable"])
            line = result.lines["cable"]
            self.assertIsInstance(line, cablefilm.Line)
            self.assertNotIsInstance(line, cablefilm.Result)
            self.assertEqual(line.name, "cable")
            assert_result_is_file(self, line, ds)
            self.assertTrue(np.shares_memory(result.tension, line.tension))
            self.assertEqual((result.peak_line, result.min_tension_line), (None, None))
            self.assertEqual((line.peak_tension, line.peak_time, line.peak_link),
                             (result.peak_tension, result.peak_time, result.peak_link))
            self.assertEqual(set(result.stats), STATS_KEYS)
            self.assertEqual(line.stats, result.stats)   # a line alone: its run's
            # Its ends are the points "start" and "end" ([ends]); no body. A point holding one
            # line end carries that end's load (points.csv's force is the same function's
            # doubles summed from zero: equal in value), at the end station's position.
            self.assertEqual(result.point_names, ["start", "end"])
            self.assertEqual(result.body_names, [])
            self.assertEqual(result.point_force.shape, (1801, 2, 3))
            self.assertEqual(result.body_pose.shape, (1801, 0, 6))
            self.assertTrue(np.array_equal(result.point_force[:, 0], result.load_start))
            self.assertTrue(np.array_equal(result.point_force[:, 1], result.load_end))
            assert_same_bits(self, result.point_position[:, 0], result.position[:, 0], "start")
            assert_same_bits(self, result.point_position[:, 1], result.position[:, -1], "end")
            # The equilibrium's line is the same, and its statics are the line's own solve's,
            # as `cablefilm check` prints them.
            assert_same_bits(self, eq.lines["cable"].tension, eq.tension, "eq.lines")
            assert_same_bits(self, eq.point_position, result.point_position[0], "eq points")
            status, stdout, stderr = cli("check", P63)
            self.assertEqual(status, 0, stderr)
            self.assertIn("static equilibrium found: %d Newton iterations, residual %.3g N"
                          % (eq.iterations, eq.residual), stdout)
            self.assertFalse(eq.fallback)
            self.assertEqual((result.stats["equilibrium_iterations"],
                              result.stats["equilibrium_residual"]), (eq.iterations, eq.residual))

    def test_tension_statistics(self):
        # The end links' statistics and spectrum of a Result, against numpy on its own rows:
        # the moments within their one-pass round-off (1e-9), the extremes and the crossings
        # exactly, the most probable maximum by its formula, m0 as the spectrum's sum.
        result = cablefilm.run(cablefilm.load(P63))
        line = result.lines["cable"]
        stats = line.tension_statistics
        spectrum = line.tension_spectrum
        self.assertEqual(set(stats), {"start", "end"})
        self.assertEqual(set(spectrum), {"frequency", "start", "end"})
        df = spectrum["frequency"][1] - spectrum["frequency"][0]
        for end, column in (("start", 0), ("end", -1)):
            x = np.asarray(line.tension[:, column])
            s = stats[end]
            self.assertEqual(s["samples"], len(x))
            self.assertAlmostEqual(s["mean"] / x.mean(), 1, delta=1e-9)
            self.assertAlmostEqual(s["std"] / x.std(), 1, delta=1e-9)
            self.assertEqual((s["min"], s["max"]), (x.min(), x.max()))
            crossings = int(np.count_nonzero((x[:-1] < s["mean"]) & (x[1:] >= s["mean"])))
            self.assertEqual(s["upcrossings"], crossings)
            self.assertGreaterEqual(crossings, 5)   # P63's minute of ship motion: cycles of 8 s
            self.assertAlmostEqual(
                s["mpm"], s["mean"] + s["std"] * math.sqrt(2 * math.log(crossings)), delta=1e-6)
            self.assertAlmostEqual(s["psd_m0"] / (spectrum[end].sum() * df), 1, delta=1e-9)

    def test_changed_value_bit_for_bit(self):
        # A value set from Python, then the program on the scene's text: the same doubles.
        scene = cablefilm.load(P63)
        scene["environment.current"] = 0.5
        scene["simulation.duration"] = 10
        self.assertEqual(scene["environment.current"], 0.5)
        out = workdir("p63_current")
        path = os.path.join(out, "scene.toml")
        with open(path, "w") as f:
            f.write(scene.text)
        with cli_results(path, out) as ds:
            result = cablefilm.run(scene)
            self.assertEqual(result.time[-1], 10.0)
            assert_result_is_file(self, result, ds)


class ThreeDimensions(unittest.TestCase):
    """Issue 19: P63 turned out of its plane by a current across it (heading 90 degrees, along
    +z) and a sway of its fairlead along z: the module's z arrays are the doubles of results.nc
    and what timeseries.csv and equilibrium.csv print, and out of the plane."""

    def test_z_matches_the_files(self):
        import csv
        scene = cablefilm.load(P63)
        scene.update({"environment.current": 0.5, "environment.current_heading": 90.0,
                      "ends.end.z_amplitudes": [0.0, 1.0], "simulation.duration": 3})
        out = workdir("p63_3d")
        path = os.path.join(out, "scene.toml")
        with open(path, "w") as f:
            f.write(scene.text)
        with cli_results(path, out) as ds:
            result = cablefilm.run(scene)
            assert_result_is_file(self, result, ds)   # z, z_start, z_end among them
            eq = cablefilm.equilibrium(scene)
            assert_same_bits(self, eq.z, ds.variables["z_equilibrium"][:].data, "z_equilibrium")
        with open(os.path.join(out, "timeseries.csv")) as f:
            rows = list(csv.DictReader(f))
        self.assertEqual([r["z_end"] for r in rows], ["%.12g" % v for v in result.z_end])
        # The end loads: the CSV's columns print the module's doubles (10 digits).
        for k, axis in enumerate("xyz"):
            for end, loads in (("start", result.load_start), ("end", result.load_end)):
                self.assertEqual([r["f%s_%s" % (axis, end)] for r in rows],
                                 ["%.10g" % v for v in loads[:, k]], "f%s_%s" % (axis, end))
        with open(os.path.join(out, "equilibrium.csv")) as f:
            stations = list(csv.DictReader(f))
        self.assertEqual([r["z"] for r in stations], ["%.12g" % v for v in eq.z])
        # The same positions as (N, 3) arrays: a run's [n, stations, 3], a view of the same
        # doubles (not writeable, as x, y, z); the equilibrium's [stations, 3].
        self.assertEqual(result.position.shape, result.x.shape + (3,))
        self.assertFalse(result.position.flags.writeable)
        for k, axis in enumerate((result.x, result.y, result.z)):
            assert_same_bits(self, result.position[..., k], axis, "position[..., %d]" % k)
        assert_same_bits(self, eq.position, np.stack([eq.x, eq.y, eq.z], axis=-1), "eq.position")
        assert_same_bits(self, result.position[:, -1], np.stack(
            [result.x_end, result.y_end, result.z_end], axis=-1), "position of the end")
        # Out of the plane: every station but the anchor and the fairlead pushed towards +z by
        # the current, the fairlead swaying as eq. (3) says along z (R(3 s) sin(0.6 pi) = 0.42 m).
        self.assertTrue(np.all(result.z[:, 1:-1] > 0))
        self.assertEqual(np.count_nonzero(result.z_start), 0)
        t = result.time
        trochoid = (1 - (1 + 0.5 * t) * np.exp(-0.5 * t)) * np.sin(2 * np.pi * t / 10)
        self.assertLess(np.max(np.abs(result.z_end - trochoid)), 1e-12)
        self.assertGreater(abs(result.z_end[-1]), 0.4)


class SceneErrors(unittest.TestCase):
    """A bad scene raises SceneError (a ValueError) with what `cablefilm check` prints."""

    def check_message(self, path):
        status, _, stderr = cli("check", path)
        self.assertEqual(status, 1, stderr)
        prefix = "cablefilm: error: "
        self.assertTrue(stderr.startswith(prefix) and stderr.endswith("\n"), stderr)
        return stderr[len(prefix):-1]

    def bad_scene(self, old, new):
        with open(P63) as f:
            text = f.read()
        self.assertIn(old, text)
        out = workdir("bad")
        path = os.path.join(out, "bad.toml")
        with open(path, "w") as f:
            f.write(text.replace(old, new, 1))
        return path

    def test_same_message_as_check(self):
        cases = [
            ("current = 0.0 ", "curent = 0.0 "),                    # unknown key
            ("youngs_modulus = 9.0e10", "youngs_modulus = -1"),     # out of range
            ("period = 10.0", "period = \"ten\""),                  # wrong type
            ("[cable]", "[cable"),                                  # not TOML
            ("position = [80.0, 30.48]", "position = [800.0, 30.48]"),  # the model's limits
        ]
        for old, new in cases:
            with self.subTest(new=new):
                path = self.bad_scene(old, new)
                expected = self.check_message(path)
                with self.assertRaises(cablefilm.SceneError) as caught:
                    cablefilm.load(path)
                self.assertIsInstance(caught.exception, ValueError)
                self.assertEqual(str(caught.exception), expected)
                # The same from run(), which loads a path itself.
                with self.assertRaises(cablefilm.SceneError) as caught:
                    cablefilm.run(path)
                self.assertEqual(str(caught.exception), expected)

    def test_missing_file(self):
        path = os.path.join(workdir("missing"), "none.toml")
        expected = self.check_message(path)
        with self.assertRaises(cablefilm.SceneError) as caught:
            cablefilm.load(path)
        self.assertEqual(str(caught.exception), expected)

    def test_bad_value_leaves_the_scene(self):
        scene = cablefilm.load(P63)
        before = scene.text
        with self.assertRaises(cablefilm.SceneError) as caught:
            scene["environment.current"] = "fast"
        self.assertIn("environment.current", str(caught.exception))
        with self.assertRaises(cablefilm.SceneError) as caught:
            scene["environment.curent"] = 0.5
        self.assertIn("environment.curent: unknown key", str(caught.exception))
        with self.assertRaises(cablefilm.SceneError) as caught:
            scene["material[2].diameter"] = 0.1
        self.assertIn("material[2]", str(caught.exception))
        with self.assertRaises(TypeError):
            scene["environment.current"] = None
        # update() sets keys together: one bad value and none is set.
        with self.assertRaises(cablefilm.SceneError):
            scene.update({"environment.current": 0.3, "simulation.duration": -1})
        self.assertEqual(scene.text, before)
        self.assertEqual(scene["environment.current"], 0.0)
        with self.assertRaises(KeyError):
            scene["environment.nothing"]


class BreakingLoad(unittest.TestCase):
    """A material's minimum_breaking_load per link, as results.nc has it (issue 21 item 5)."""

    def test_mbl_per_link_and_utilisation(self):
        with open(P63, encoding="utf-8") as f:
            text = f.read()
        text = text.replace('name = "wire"', 'name = "wire"\nminimum_breaking_load = 10e3', 1)
        text = text.replace('name = "nylon"', 'name = "nylon"\nminimum_breaking_load = 100e3', 1)
        text = text.replace("duration = 60.0", "duration = 2.0", 1)
        path = os.path.join(workdir("mbl"), "p63_mbl.toml")
        with open(path, "w", encoding="utf-8") as f:
            f.write(text)
        out = workdir("mbl_cli")
        with cli_results(path, out) as ds:
            result = cablefilm.run(cablefilm.load(path))
            mbl = result.minimum_breaking_load
            assert_same_bits(self, mbl, ds.variables["minimum_breaking_load"][:].data, "mbl")
            self.assertEqual(list(mbl[:30]), [10e3] * 30)    # the wire's 30 links
            self.assertEqual(list(mbl[30:]), [100e3] * 30)   # the nylon's
            # The utilisation from the arrays against timeseries.csv's column (10 digits).
            with open(os.path.join(out, "timeseries.csv"), encoding="utf-8") as f:
                rows = list(csv.DictReader(f))
            ours = (result.tension / mbl).max(axis=1)
            theirs = np.array([float(r["utilisation_max"]) for r in rows])
            np.testing.assert_allclose(theirs, ours, rtol=1e-9)


class DictScenes(unittest.TestCase):
    """A scene given as a dict is read by the same loader: same results, same checks."""

    def test_dict_equals_file(self):
        with open(P63, "rb") as f:
            d = tomllib.load(f)
        d["simulation"]["duration"] = 20.0
        from_dict = cablefilm.run(cablefilm.load(d))
        from_file = cablefilm.load(P63)
        from_file["simulation.duration"] = 20.0
        from_file = cablefilm.run(from_file)
        for name in ["time", "x", "y", "z", "tension"]:
            assert_same_bits(self, getattr(from_dict, name), getattr(from_file, name), name)
        # to_dict() gives the dict back; a numpy value is taken as its Python value.
        self.assertEqual(cablefilm.load(d).to_dict(), d)
        scene = cablefilm.load(d)
        scene["ends.end.x_amplitudes"] = np.array([1.8288, 0.0])
        scene["cable.section[0].segments"] = np.int64(30)
        self.assertEqual(scene["ends.end.x_amplitudes"], [1.8288, 0.0])
        self.assertEqual(scene["cable.section[0].segments"], 30)

    def test_dict_errors_name_the_key(self):
        with open(P63, "rb") as f:
            d = tomllib.load(f)
        d["environment"]["curent"] = 0.5
        with self.assertRaises(cablefilm.SceneError) as caught:
            cablefilm.load(d, name="p63")
        message = str(caught.exception)
        self.assertTrue(message.startswith("p63:"), message)
        self.assertIn("environment.curent: unknown key", message)
        with self.assertRaises(TypeError):
            cablefilm.load({"environment": {"current": object()}})

    def test_circular_and_deep_values_are_errors(self):
        # Issue 22 item 2: these recursed in the TOML conversion until the interpreter died
        # (SIGSEGV). A ValueError naming the key, as json.dumps gives one; the module still works.
        with open(P63, "rb") as f:
            d = tomllib.load(f)
        d["environment"]["loop"] = d
        with self.assertRaisesRegex(ValueError, r"^environment\.loop: .*circular reference"):
            cablefilm.load(d)
        del d["environment"]["loop"]
        deep = []
        for _ in range(100000):
            deep = [deep]

        class Endless:  # tolist() gives another of its kind, for ever
            def tolist(self):
                return Endless()

        class Itself:  # tolist() gives a list holding it
            def tolist(self):
                return [self]

        for value, message in [(deep, r"nested more than 64 levels"),
                               (Endless(), r"nested more than 64 levels"),
                               (Itself(), r"circular reference")]:
            d["environment"]["current"] = value
            with self.assertRaisesRegex(ValueError, r"^environment\.current\b.*" + message):
                cablefilm.load(d)
            scene = cablefilm.load(P63)
            with self.assertRaisesRegex(ValueError, message):
                scene["environment.current"] = value
            with self.assertRaisesRegex(ValueError, message):
                cablefilm.sweep(scene, {"environment.current": [value]})
            with self.assertRaisesRegex(ValueError, message):
                cablefilm.sweep(scene, cases=[{"environment.current": value}])
        # Nesting within the limit is converted (a scene's own tables nest three deep).
        d["environment"]["current"] = 0.0
        self.assertEqual(cablefilm.load(d)["environment.current"], 0.0)
        shared = [1.0, 0.0]  # one list twice is no cycle
        d["ends"]["end"]["x_amplitudes"] = shared
        d["ends"]["end"]["y_amplitudes"] = shared
        self.assertEqual(cablefilm.load(d)["ends.end.y_amplitudes"], [1.0, 0.0])


class Equilibrium(unittest.TestCase):
    """A chain hanging between two fixed ends: the static balance worked out by hand."""

    def test_hanging_chain_balance(self):
        L, links, span = 100.0, 50, 80.0              # m, links, m between the ends
        mu, area, E, rho, g = 10.0, 1e-3, 2e11, 1025.0, 9.80665
        scene = cablefilm.load({
            "title": "hanging chain",
            "environment": {"gravity": g, "fluid_density": rho, "current": 0.0},
            "material": [{"name": "chain", "diameter": 0.05, "area": area,
                          "mass_per_length": mu, "youngs_modulus": E}],
            "cable": {"section": [{"material": "chain", "length": L, "segments": links}]},
            "ends": {"start": {"position": [0.0, 0.0], "motion": "fixed"},
                     "end": {"position": [span, 0.0], "motion": "fixed"}},
        }, name="chain")
        x, y, T = cablefilm.equilibrium(scene)
        self.assertEqual((x.shape, y.shape, T.shape), ((links + 1,), (links + 1,), (links,)))
        # The interior stations carry the net weight of the cable but half a link at each end
        # (those halves rest on the ends): the vertical pulls of the end links balance it.
        w = (mu - rho * area) * g                      # net weight per metre [N/m]
        carried = w * (L - L / links)                  # [N]
        def vertical_pull(j0, j1, t):
            dx, dy = x[j1] - x[j0], y[j1] - y[j0]
            return t * dy / np.hypot(dx, dy)
        pulls = vertical_pull(1, 0, T[0]) + vertical_pull(links - 1, links, T[-1])
        # The solver stops at a residual of 1e-9 of its force scale; 1e-6 leaves room.
        self.assertAlmostEqual(pulls / carried, 1.0, delta=1e-6)
        # Symmetric ends, symmetric line: the lowest station in the middle.
        self.assertEqual(int(np.argmin(y)), links // 2)
        self.assertAlmostEqual(T[0], T[-1], delta=1e-6 * T[0])


class Threads(unittest.TestCase):
    """Runs release the GIL: two Python threads running cases give the serial results."""

    def test_two_threads_same_as_serial(self):
        scenes = []
        for current in [0.1, 0.4]:
            s = cablefilm.load(P63)
            s.update({"environment.current": current, "simulation.duration": 20})
            scenes.append(s)
        serial = [cablefilm.run(s) for s in scenes]
        threaded = [None, None]
        def work(i):
            threaded[i] = cablefilm.run(scenes[i])
        threads = [threading.Thread(target=work, args=(i,)) for i in range(2)]
        for t in threads:
            t.start()
        for t in threads:
            t.join()
        for a, b in zip(serial, threaded):
            for name in ["time", "x", "y", "tension"]:
                assert_same_bits(self, getattr(a, name), getattr(b, name), name)
        # The two cases differ (else the test proves little).
        self.assertNotEqual(serial[0].peak_tension, serial[1].peak_tension)


class Sweep(unittest.TestCase):
    """cablefilm.sweep against `cablefilm sweep`'s sweep.csv and single runs."""

    def test_sweep_matches_cli_and_runs(self):
        base = cablefilm.load(P63)
        base.update({"simulation.duration": 5, "output.interval": 0.1})
        out = workdir("sweep")
        path = os.path.join(out, "base.toml")
        with open(path, "w") as f:
            f.write(base.text)
        values = {"environment.current": [0.0, 0.5], "ends.end.period": [8, 12]}
        rows = cablefilm.sweep(base, values, jobs=2)
        self.assertEqual(len(rows), 4)
        status, stdout, stderr = cli("sweep", path, "--set", "environment.current=0.0,0.5",
                                     "--set", "ends.end.period=8,12", "--jobs", "2",
                                     "--out", os.path.join(out, "cli"))
        self.assertEqual(status, 0, stdout + stderr)
        import csv
        with open(os.path.join(out, "cli", "sweep.csv")) as f:
            csv_rows = list(csv.DictReader(f))
        for row, csv_row in zip(rows, csv_rows):
            self.assertEqual(row["status"], "ok")
            self.assertEqual(row["status"], csv_row["status"])
            for key in values:
                self.assertEqual(float(row[key]), float(csv_row[key]))
            # sweep.csv has 10 significant digits.
            for name in ["peak_tension", "peak_time", "min_tension", "min_tension_time"]:
                self.assertAlmostEqual(row[name], float(csv_row[name]),
                                       delta=abs(row[name]) * 1e-9 + 1e-300, msg=name)
            for name in ["peak_link", "min_tension_link", "snaps"]:
                self.assertEqual(row[name], int(csv_row[name]), name)
            self.assertEqual(str(row["peak_converged"]).lower(), csv_row["peak_converged"])
            single = base.copy()
            single.update({k: row[k] for k in values})
            self.assertEqual(row["peak_tension"], cablefilm.run(single).peak_tension)

    def test_sweep_of_a_moordyn_file(self):
        # Its keys are those of its equivalent scene (`cablefilm convert`): the chain's 50 kg/m
        # and twice that, as `cablefilm sweep` runs them.
        leg = os.path.join(SOURCE, "tests", "scenes", "moordyn", "one_leg.txt")
        self.assertEqual(cablefilm.load(leg)["material[0].mass_per_length"], 50.0)
        rows = cablefilm.sweep(leg, {"material[0].mass_per_length": [50, 100]}, jobs=1)
        out = workdir("sweep_moordyn")
        status, stdout, stderr = cli("sweep", leg, "--set", "material[0].mass_per_length=50,100",
                                     "--jobs", "1", "--out", out)
        self.assertEqual(status, 0, stdout + stderr)
        import csv
        with open(os.path.join(out, "sweep.csv")) as f:
            csv_rows = list(csv.DictReader(f))
        self.assertEqual([r["status"] for r in rows], ["ok", "ok"])
        for row, csv_row in zip(rows, csv_rows):
            for name in ["peak_tension", "min_tension"]:
                self.assertAlmostEqual(row[name], float(csv_row[name]),
                                       delta=abs(row[name]) * 1e-9, msg=name)
        self.assertEqual(rows[0]["peak_tension"], cablefilm.run(leg).peak_tension)
        self.assertGreater(rows[1]["peak_tension"], 1.9 * rows[0]["peak_tension"])

    def test_refused_case(self):
        with self.assertRaises(cablefilm.SceneError) as caught:
            cablefilm.sweep(P63, {"environment.curent": [0]})
        self.assertIn("case 0 (environment.curent = 0) is refused, so no case was run",
                      str(caught.exception))


def read_png(path):
    """An 8-bit RGB or RGBA, non-interlaced PNG as an (H, W, channels) array (zlib only)."""
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, header = 8, b"", None
    while pos < len(data):
        length, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + length]
        if kind == b"IHDR":
            header = struct.unpack(">IIBBBBB", body)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + length
    width, height, depth, color, _, _, interlace = header
    assert depth == 8 and color in (2, 6) and interlace == 0, header
    channels = 3 if color == 2 else 4
    raw = np.frombuffer(zlib.decompress(idat), dtype=np.uint8)
    stride = width * channels
    rows = raw.reshape(height, stride + 1)
    out = np.zeros((height, stride), dtype=np.int32)
    prev = np.zeros(stride, dtype=np.int32)
    for r in range(height):
        kind, line = rows[r, 0], rows[r, 1:].astype(np.int32)
        cur = np.zeros(stride, dtype=np.int32)
        for i in range(stride):
            a = cur[i - channels] if i >= channels else 0
            b = prev[i]
            c = prev[i - channels] if i >= channels else 0
            if kind == 0:
                p = 0
            elif kind == 1:
                p = a
            elif kind == 2:
                p = b
            elif kind == 3:
                p = (a + b) // 2
            else:
                pa, pb, pc = abs(b - c), abs(a - c), abs(a + b - 2 * c)
                p = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            cur[i] = (line[i] + p) & 0xFF
        out[r] = cur
        prev = cur
    return out.reshape(height, width, channels).astype(np.uint8)


class Pictures(unittest.TestCase):
    """A frame as an array, and the film, drawn by the film pass of the program."""

    def frame_against_film(self, scene_file, options, t, frame_number):
        scene = cablefilm.load(os.path.join(SOURCE, "scenes", scene_file))
        scene["simulation.duration"] = 2
        out = workdir("frames")
        path = os.path.join(out, "scene.toml")
        with open(path, "w") as f:
            f.write(scene.text)
        status, stdout, stderr = cli("run", path, "--frames", "--size", "320x180", "--out", out,
                                     *options)
        self.assertEqual(status, 0, stdout + stderr)
        result = cablefilm.run(scene)
        frame = cablefilm.render_frame(result, t, width=320, height=180)
        self.assertEqual(frame.shape, (180, 320, 3))
        self.assertEqual(frame.dtype, np.uint8)
        # Not a blank picture: the cable's colour map, the plots, the text.
        colours = np.unique(frame.reshape(-1, 3), axis=0)
        self.assertGreater(len(colours), 100)
        png = read_png(os.path.join(out, "frames", "frame_%06d.png" % frame_number))[:, :, :3]
        differ = np.count_nonzero(np.any(png != frame, axis=2))
        self.assertEqual(differ, 0, "%s: %d of %d pixels differ from the film's frame %d"
                         % (scene_file, differ, frame.shape[0] * frame.shape[1], frame_number))
        other = cablefilm.render_frame(result, row=0, width=320, height=180)
        self.assertTrue(np.any(other != frame))

    def test_frame_is_the_films_frame(self):
        # P63: 30 frames a second, a row a frame: frame 30 is t = 1 s.
        self.frame_against_film("polachek1963.toml", [], 1.0, 30)

    def test_frame_in_waves_is_the_films_frame(self):
        # A row every 0.1 s; at 3 simulated seconds per second of film, a row a frame: frame 10
        # is t = 1 s, with the water surface.
        self.frame_against_film("grounded_mooring.toml", ["--speed", "3"], 1.0, 10)

    def test_film(self):
        scene = cablefilm.load(P63)
        scene["simulation.duration"] = 1
        out = workdir("film")
        film = os.path.join(out, "p63.mp4")
        self.assertEqual(cablefilm.render_film(scene, film, width=320, height=180), film)
        with open(film, "rb") as f:
            head = f.read(12)
        self.assertEqual(head[4:8], b"ftyp")
        self.assertEqual(os.listdir(out), ["p63.mp4"])   # nothing else left beside it
        with self.assertRaises(ValueError):
            cablefilm.render_film(scene, film, width=321)
        # A window of the run: within it, or refused naming the window before anything is made.
        part = os.path.join(out, "part.mp4")
        self.assertEqual(cablefilm.render_film(scene, part, width=320, height=180,
                                               window="0.5,1"), part)
        with self.assertRaisesRegex(ValueError, "window: expected a window within the run, "
                                                "from 0 to 1 s, got 0.5 to 2 s"):
            cablefilm.render_film(scene, part, window="0.5,2")
        with self.assertRaisesRegex(ValueError, "window: expected peak:SECONDS"):
            cablefilm.render_film(scene, part, window="peak:-1")
        os.remove(part)
        with self.assertRaises(ValueError):
            cablefilm.render_frame(scene, colormap="rainbow")
        # A Line is drawn with its run: render_frame and render_film take the Result.
        result = cablefilm.run(scene)
        with self.assertRaisesRegex(TypeError, "Result"):
            cablefilm.render_frame(result.lines["cable"])
        with self.assertRaisesRegex(TypeError, "Result"):
            cablefilm.render_film(result.lines["cable"], os.path.join(workdir("film"), "l.mp4"))


if __name__ == "__main__":
    unittest.main()
