#!/usr/bin/env python3
"""Issue 22: a fuzzer of the Python module's dict scenes.

Each case takes a shipped scene (scenes/*.toml) as the dict `tomllib` gives, makes ONE change
to a value or a key (a hostile number, a value of another type, a nested container, a very long
string, deep nesting, a dict or list that contains itself, numpy values, a key deleted, added or
not a string, an entry of an array of tables duplicated), then calls cablefilm.load, reads the
Scene back (to_dict, scene[key]), cablefilm.equilibrium and a short cablefilm.run, each within
a time budget (SIGALRM: the module's calls stop as Ctrl-C stops them).

A case passes when every call either succeeds with finite results or raises one of the module's
documented exceptions: cablefilm.SceneError (a ValueError), cablefilm.BlowUpError (a
RuntimeError), TypeError, ValueError; a RecursionError, a MemoryError, SystemError or any other
exception fails it. The cases run in one child process under a parent that sees a signal death
(a crash, an abort): that case fails too. Every failing case is written to
tests/python/dict_fuzz_regressions/ as JSON (the scene's file name and the change, values
spelled as tagged JSON: {"$float": "nan"}, {"$self": []}, {"$deep": n}, ...) and the run fails;
--replay runs the saved cases alone (a plain run replays them first).

    dict_fuzz.py [--seconds 20] [--seed 22] [--replay] [--regressions DIR]

Needs PYTHONPATH with the module (<build>/python) and CABLEFILM_SOURCE_DIR (or runs from the
source tree). The seed is printed; the same seed and the same scenes give the same cases.
"""
import argparse
import copy
import glob
import json
import math
import os
import random
import re
import signal
import subprocess
import sys
import tempfile
import time
import tomllib
import traceback
import warnings

HERE = os.path.dirname(os.path.abspath(__file__))
SOURCE = os.environ.get("CABLEFILM_SOURCE_DIR", os.path.dirname(os.path.dirname(HERE)))
SCENES = os.path.join(SOURCE, "scenes")
REGRESSIONS = os.path.join(HERE, "dict_fuzz_regressions")
BUDGET = 1.0        # s of a call (load, equilibrium, run) before it is stopped
RUN_SECONDS = 2.0   # the simulated time of the base scenes (a short run)


class Budget(Exception):
    """The call's time is over (raised by the SIGALRM handler, through the module's checks)."""


# ---- values, spelled as JSON ----

def hostile_number(rng, x):
    choices = [0, 0.0, -0.0, -x, 1e-300, -1e-300, 1e300, -1e300, 5e-324, 1.7976931348623157e308,
               x * (1 + 1e-12), x * (1 - 1e-12), x * 10, x / 10 if x else 0.1,
               {"$float": "nan"}, {"$float": "inf"}, {"$float": "-inf"},
               2 ** 63 - 1, -2 ** 63, 2 ** 63, 2 ** 64, 10 ** 30, -(10 ** 30), 2 ** 53 + 1,
               1, -1, 10 ** 7, 10 ** 7 + 1, int(x) if math.isfinite(x) else 0,
               rng.uniform(-1e3, 1e3), rng.choice([1e-12, 1e-9, 1e-6, 1e6, 1e9, 1e12, 1e13])]
    v = rng.choice(choices)
    if isinstance(v, float) and not math.isfinite(v):
        return {"$float": repr(v)}
    return v


def other_value(rng, scene_strings):
    """A value of any type: wrong types, containers, long strings, deep or circular values."""
    k = rng.randrange(22)
    if k == 0: return None
    if k == 1: return rng.choice([True, False])
    if k == 2: return []
    if k == 3: return {}
    if k == 4: return [1.0, 2.0, 3.0, 4.0]
    if k == 5: return [[1.0, 2.0], [3.0]]
    if k == 6: return {"x": 1, "y": [1, {"z": None}]}
    if k == 7: return "x" * rng.choice([1000, 100000, 1000000])
    if k == 8: return rng.choice(["", "\x00", "\ud800", "\u2028", "e\u0301", "../../etc/passwd",
                                  "/dev/zero", "elastic", "inextensible", "fixed", "free",
                                  "trochoid", "table", "wave", "auto", "equilibrium",
                                  "straight", "explicit", "3d", "motion.csv"] + scene_strings)
    if k == 9: return {"$deep": rng.choice([10, 63, 64, 65, 1000, 100000]),
                       "kind": rng.choice(["list", "dict", "tuple"])}
    if k == 10: return {"$self": rng.choice(["root", "parent"])}
    if k == 11: return {"$bytes": "00ff"}
    if k == 12: return {"$complex": [1.0, 2.0]}
    if k == 13: return {"$numpy": rng.choice(["float32", "float64", "int64", "int8", "uint64",
                                              "bool_", "float16"]),
                        "value": rng.choice([1.5, 0, -1, 1e30, 255])}
    if k == 14: return {"$ndarray": rng.choice([[1.0, 2.0], [[1.0, 2.0], [3.0, 4.0]], [],
                                                [1.0, 2.0, 3.0]]),
                        "dtype": rng.choice(["float64", "float32", "int64", "object"])}
    if k == 15: return {"$tolist": rng.choice(["endless", "itself", "raises", "none"])}
    if k == 16: return {"$tuple": [1.0, 2.0]}
    if k == 17: return {"$set": [1.0, 2.0]}
    if k == 18: return {"$object": 1}
    if k == 19: return {"$float": "nan"}
    if k == 20: return [{"$float": "inf"}, 1.0]
    return rng.choice([0, 1, -1, 0.5, 2 ** 64, "1.0"])


class Endless:
    """tolist() gives another of its kind, for ever."""
    def tolist(self):
        return Endless()


class Itself:
    """tolist() gives a list holding it."""
    def tolist(self):
        return [self]


class Raises:
    def tolist(self):
        raise ValueError("tolist refused")


class NoneList:
    def tolist(self):
        return None


def materialize(spec, root, parent):
    """The Python value a JSON spec stands for (root, parent: for self-references)."""
    import numpy as np
    if isinstance(spec, list):
        return [materialize(v, root, parent) for v in spec]
    if not isinstance(spec, dict):
        return spec
    if "$float" in spec:
        return float(spec["$float"])
    if "$deep" in spec:
        v = 1.0
        for _ in range(spec["$deep"]):
            v = {"a": v} if spec["kind"] == "dict" else (v,) if spec["kind"] == "tuple" else [v]
        return v
    if "$self" in spec:
        return root if spec["$self"] == "root" else parent
    if "$bytes" in spec:
        return bytes.fromhex(spec["$bytes"])
    if "$complex" in spec:
        return complex(*spec["$complex"])
    if "$numpy" in spec:
        return getattr(np, spec["$numpy"])(spec["value"])
    if "$ndarray" in spec:
        return np.array(spec["$ndarray"], dtype=spec["dtype"])
    if "$tolist" in spec:
        return {"endless": Endless, "itself": Itself, "raises": Raises,
                "none": NoneList}[spec["$tolist"]]()
    if "$tuple" in spec:
        return tuple(spec["$tuple"])
    if "$set" in spec:
        return set(spec["$set"])
    if "$object" in spec:
        return object()
    if "$int" in spec:
        return int(spec["$int"])
    return {k: materialize(v, root, parent) for k, v in spec.items()}


# ---- the cases ----

def base_scene(name):
    with open(os.path.join(SCENES, name), "rb") as f:
        d = tomllib.load(f)
    sim = d.setdefault("simulation", {})
    sim["duration"] = min(float(sim.get("duration", 60.0)), RUN_SECONDS)
    d.setdefault("output", {})["film"] = False
    return d


def slots(d, path=()):
    """Every (path, value) of the dict, depth first."""
    out = []
    items = d.items() if isinstance(d, dict) else enumerate(d)
    for k, v in items:
        p = path + (k,)
        out.append((p, v))
        if isinstance(v, (dict, list)):
            out.extend(slots(v, p))
    return out


def strings_of(d):
    return [v for _, v in slots(d) if isinstance(v, str)]


KNOWN_KEYS = ["gravity", "fluid_density", "current", "current_heading", "y", "stiffness",
              "damping", "friction", "friction_velocity", "friction_model", "friction_stiffness",
              "height", "period", "depth",
              "surface_y", "phase", "heading", "ramp_rate", "name", "diameter", "area",
              "mass_per_length", "youngs_modulus", "drag_coefficient", "added_mass_coefficient",
              "axial_damping", "axial_damping_ratio", "tangential_drag_coefficient",
              "tangential_added_mass_coefficient", "axial_froude_krylov", "kinematics",
              "minimum_breaking_load", "interpolation",
              "model", "material", "length", "segments",
              "at", "mass", "volume", "added_volume", "drag_area", "position", "motion",
              "x_amplitudes", "y_amplitudes", "z_amplitudes", "file", "x_rao", "y_rao", "state",
              "duration", "integrator", "time_step", "tolerance", "rho_infinity",
              "start_tolerance", "start_duration",
              "safety_factor", "width", "height", "fps", "speed", "crf", "colormap",
              "tension_range", "view", "interval", "film", "frames", "start", "end", "force",
              "seabed", "waves", "title", "point", "line"]


def make_case(rng, scene_names):
    """A case: a scene's file name and one change (JSON)."""
    scene = rng.choice(scene_names)
    d = base_scene(scene)
    all_slots = slots(d)
    tables = [p for p, v in all_slots if isinstance(v, dict)] + [()]
    k = rng.randrange(10)
    path, value = rng.choice(all_slots)
    if k < 4 and isinstance(value, (int, float)) and not isinstance(value, bool):
        return {"scene": scene, "op": "set", "path": list(path),
                "value": hostile_number(rng, float(value))}
    if k < 6:
        return {"scene": scene, "op": "set", "path": list(path),
                "value": other_value(rng, strings_of(d))}
    if k == 6:
        return {"scene": scene, "op": "del", "path": list(path)}
    if k == 7:
        lists = [p for p, v in all_slots if isinstance(v, list) and v]
        if lists:
            p = rng.choice(lists)
            return {"scene": scene, "op": "dup", "path": list(p)}
    table = rng.choice(tables)
    key = rng.choice(KNOWN_KEYS + [{"$int": 5}, "", "x" * 10000, "a.b", "\ud800", " "])
    value = (hostile_number(rng, 1.0) if rng.randrange(2) else other_value(rng, strings_of(d)))
    return {"scene": scene, "op": "key", "path": list(table), "key": key, "value": value}


def apply_case(case):
    """The dict of the case's scene with its change."""
    d = base_scene(case["scene"])
    path = case["path"]
    parent = d
    for p in (path[:-1] if case["op"] in ("set", "del") else path):
        parent = parent[p]
    if case["op"] == "set":
        parent[path[-1]] = materialize(case["value"], d, parent)
    elif case["op"] == "del":
        del parent[path[-1]]
    elif case["op"] == "dup":  # the last entry again (an array of tables: one more [[...]])
        parent.append(copy.deepcopy(parent[-1]))
    elif case["op"] == "key":
        key = materialize(case["key"], d, parent)
        parent[key] = materialize(case["value"], d, parent)
    return d


def alarm(_signum, _frame):
    raise Budget()


def timed(call, *args):
    signal.setitimer(signal.ITIMER_REAL, BUDGET)
    try:
        return call(*args)
    finally:
        signal.setitimer(signal.ITIMER_REAL, 0)


def finite(name, a):
    import numpy as np
    a = np.asarray(a, dtype=np.float64)
    if not np.all(np.isfinite(a)):
        raise AssertionError("%s is not finite (%d of %d values)"
                             % (name, np.count_nonzero(~np.isfinite(a)), a.size))


REACHED = {"loaded": 0, "equilibrium": 0, "run": 0}  # calls that succeeded


def finite_parts(what, result, own_names, line_names):
    """A Result or an Equilibrium, of one line or several: `own_names` finite, and each line's
    `line_names`."""
    for name in own_names:
        finite(what + "." + name, getattr(result, name))
    for line, part in result.lines.items():
        for name in line_names:
            finite("%s.lines[%s].%s" % (what, line, name), getattr(part, name))


def run_case(case):
    """Returns None when the case passes, else what went wrong."""
    import cablefilm
    allowed = (cablefilm.SceneError, cablefilm.BlowUpError, TypeError, ValueError, Budget)
    try:
        d = apply_case(case)
    except (OverflowError, ValueError, TypeError):
        return None  # numpy refused to make the value (np.int8(1e30)): no case
    try:
        try:
            scene = timed(cablefilm.load, d)
            REACHED["loaded"] += 1
        except allowed:
            return None
        try:
            back = scene.to_dict()
            if back:
                scene[next(iter(back))]
        except KeyError:
            pass  # a table as a key the scene's getter does not take
        try:
            e = timed(cablefilm.equilibrium, scene)
            finite_parts("equilibrium", e,
                         ("point_position", "point_force", "body_pose", "body_load", "residual"),
                         ("x", "y", "z", "tension", "residual"))
            REACHED["equilibrium"] += 1
        except allowed:
            pass
        try:
            r = timed(cablefilm.run, scene)
            finite_parts("run", r, ("time", "point_position", "point_force", "body_pose",
                                    "body_load", "peak_tension"),
                         ("time", "x", "y", "z", "tension", "peak_tension"))
            REACHED["run"] += 1
        except allowed:
            pass
    except RecursionError as e:  # a RuntimeError, but not one the module means
        return "RecursionError: %s" % str(e)[:500]
    except AssertionError as e:
        return "not finite: %s" % e
    except Budget:  # the alarm after a call had returned
        return None
    except BaseException as e:  # noqa: BLE001: anything else is a failure
        if isinstance(e, KeyboardInterrupt):
            raise
        return "%s: %s\n%s" % (type(e).__name__, str(e)[:500], traceback.format_exc()[-2000:])
    return None


def save(case, why, directory):
    os.makedirs(directory, exist_ok=True)
    kind = re.sub(r"\W+", "_", why.split(":")[0]).strip("_").lower()
    name = "%s_%s_%s.json" % (kind, os.path.splitext(case["scene"])[0],
                              case.get("id", "%d" % int(time.time() * 1000)))
    path = os.path.join(directory, name)
    with open(path, "w") as f:
        json.dump(dict(case, why=why.splitlines()[0]), f, indent=1)
        f.write("\n")
    return path


# ---- the child: the cases themselves ----

def child(args):
    warnings.simplefilter("ignore")  # numpy's overflow warnings while the values are made
    signal.signal(signal.SIGALRM, alarm)
    sys.setrecursionlimit(10000)
    failures = 0
    current = args.current
    cases = []
    for path in sorted(glob.glob(os.path.join(args.regressions, "*.json"))):
        with open(path) as f:
            c = json.load(f)
        c.pop("why", None)
        cases.append((os.path.basename(path), c))
    scene_names = sorted(os.path.basename(p) for p in glob.glob(os.path.join(SCENES, "*.toml")))
    rng = random.Random(args.seed)
    stats = {"cases": 0, "passed": 0}

    def one(label, case):
        nonlocal failures
        with open(current, "w") as f:  # what the parent keeps if this case kills the process
            json.dump(dict(case, saved=label) if label.endswith(".json") else case, f)
        why = run_case(case)
        stats["cases"] += 1
        if why is None:
            stats["passed"] += 1
            return
        failures += 1
        print("dict_fuzz: FAILURE in %s: %s\n  %s" % (label, why.splitlines()[0],
                                                      json.dumps(case)[:400]), flush=True)
        if not label.endswith(".json"):
            print("  written to %s" % save(case, why, args.regressions), flush=True)

    if not args.skip_saved:
        for label, case in cases:
            one(label, case)
    replayed = stats["cases"]
    if not args.replay:
        end = time.monotonic() + args.seconds
        i = 0
        while time.monotonic() < end:
            case = make_case(rng, scene_names)
            case["id"] = "%d_%d" % (args.seed, i)
            if i == args.crash_at:  # a check of this script: the parent must see it
                with open(current, "w") as f:
                    json.dump(case, f)
                os.abort()
            one("case %s" % case["id"], case)
            i += 1
    print("dict_fuzz: %d saved case(s) replayed, %d case(s) in all, %d passed; %d loaded, %d "
          "equilibria and %d runs succeeded with finite results"
          % (replayed, stats["cases"], stats["passed"], REACHED["loaded"],
             REACHED["equilibrium"], REACHED["run"]), flush=True)
    return 1 if failures else 0


# ---- the parent: sees a crash ----

def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--seconds", type=float, default=20.0)
    ap.add_argument("--seed", type=int, default=22)
    ap.add_argument("--replay", action="store_true", help="only the saved cases")
    ap.add_argument("--regressions", default=REGRESSIONS)
    ap.add_argument("--child", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--current", help=argparse.SUPPRESS)
    ap.add_argument("--skip-saved", action="store_true", help=argparse.SUPPRESS)
    ap.add_argument("--crash-at", type=int, default=-1,
                    help="abort at that case (a check that a crash is seen and kept)")
    args = ap.parse_args()
    if args.child:
        return child(args)
    print("dict_fuzz: seed %d, %g s%s" % (args.seed, args.seconds,
                                          ", saved cases only" if args.replay else ""),
          flush=True)
    status = 0
    with tempfile.TemporaryDirectory(prefix="dict_fuzz_") as tmp:
        current = os.path.join(tmp, "current.json")
        seed = args.seed
        deadline = time.monotonic() + args.seconds
        replay = args.replay
        skip_saved = False
        while True:
            seconds = max(0.0, deadline - time.monotonic())
            cmd = [sys.executable, os.path.abspath(__file__), "--child", "--current", current,
                   "--seconds", str(seconds), "--seed", str(seed),
                   "--regressions", args.regressions, "--crash-at", str(args.crash_at)] + \
                (["--replay"] if replay else []) + \
                (["--skip-saved"] if skip_saved else [])
            r = subprocess.run(cmd)
            if r.returncode >= 0:
                return r.returncode or status
            # A signal killed the child: the case it was running is kept, and the rest goes on
            # with the next seed.
            status = 1
            with open(current) as f:
                case = json.load(f)
            why = "crash: signal %d" % -r.returncode
            print("dict_fuzz: FAILURE: the process died of signal %d in %s" %
                  (-r.returncode, json.dumps(case)[:400]), flush=True)
            if "saved" not in case:
                print("  written to %s" % save(case, why, args.regressions), flush=True)
            if replay or time.monotonic() >= deadline:
                return status
            seed += 1000  # the cases after it, from another seed; the saved ones not again
            skip_saved = True


if __name__ == "__main__":
    sys.exit(main())
