#!/usr/bin/env python3
"""The layers of src/ depend one way (issue 18):

    core <- scene <- run <- {io, encode, view} <- {app, live, python} <- {modules, main.cpp}

Reads every #include "folder/..." of src/ and fails, naming the file, the line and the rule,
on an include from a folder up to a higher layer (core, scene or run up to anything above
them; io, encode or view up to a front end) and on any include between two front ends (app,
live and python never include each other). A folder of src/ that is not in the table below is
a failure too: a new folder is placed in the layers when it is made.

With --tests, the tests of tests/<layer>/ are held to the same table: a test lives in the
folder of the highest layer it includes (src's headers and the other folders' test helpers,
"../run/scene_line.h"), so tests/core/ tests the engine alone and needs nothing above it.
Folders of tests/ that are not a layer (fuzz, docs, scenes, ...) test the whole program.
"""
import argparse
import pathlib
import re
import sys

LAYER = {"core": 0, "scene": 1, "run": 2, "io": 3, "encode": 3, "view": 3,
         "app": 4, "live": 4, "python": 4, "modules": 5}
FRONT_ENDS = {"app", "live", "python"}
INCLUDE = re.compile(r'^\s*#\s*include\s*"([a-z_]+)/')
TEST_INCLUDE = re.compile(r'^\s*#\s*include\s*"(?:\.\./)?([a-z_]+)/')


def problems(src):
    found = []
    for path in sorted(src.rglob("*")):
        if path.suffix not in {".h", ".cpp", ".in"} or not path.is_file():
            continue
        rel = path.relative_to(src)
        here = rel.parts[0] if len(rel.parts) > 1 else None  # None: src/main.cpp, on top
        if here is not None and here not in LAYER:
            found.append(f"{rel}: the folder {here}/ is in no layer (tests/layers/layers_test.py)")
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = INCLUDE.match(line)
            if not m or here is None:
                continue
            there = m.group(1)
            if there not in LAYER:
                continue  # not one of ours (a system header with a folder, say)
            if LAYER[there] > LAYER[here]:
                found.append(f"{rel}:{number}: {here}/ includes {there}/, a higher layer")
            elif here != there and here in FRONT_ENDS and there in FRONT_ENDS:
                found.append(f"{rel}:{number}: the front end {here}/ includes the front end {there}/")
    return found


def test_problems(tests):
    found = []
    for path in sorted(tests.rglob("*")):
        if path.suffix not in {".h", ".cpp"} or not path.is_file():
            continue
        rel = path.relative_to(tests)
        here = rel.parts[0]
        if here not in LAYER:
            continue
        for number, line in enumerate(path.read_text(errors="replace").splitlines(), 1):
            m = TEST_INCLUDE.match(line)
            if not m:
                continue
            there = m.group(1)
            if there in LAYER and LAYER[there] > LAYER[here]:
                found.append(f"tests/{rel}:{number}: a test of {here}/ includes {there}/, a "
                             f"higher layer (it belongs in tests/{there}/)")
            elif here != there and here in FRONT_ENDS and there in FRONT_ENDS:
                found.append(f"tests/{rel}:{number}: a test of {here}/ includes the front end "
                             f"{there}/")
    return found


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--src", required=True, type=pathlib.Path)
    parser.add_argument("--tests", type=pathlib.Path, help="the tests/ folder, held to the layers")
    parser.add_argument("--self-test", action="store_true",
                        help="check that the rules catch a wrong include (a scratch copy)")
    args = parser.parse_args()
    found = problems(args.src)
    if args.tests:
        found += test_problems(args.tests)
    for p in found:
        print("FAIL:", p)
    if args.self_test:
        import shutil
        import tempfile
        with tempfile.TemporaryDirectory() as tmp:
            copy = pathlib.Path(tmp) / "src"
            shutil.copytree(args.src, copy)
            cases = {"core/forces.cpp": '#include "run/driver.h"',
                     "run/sweep_plan.cpp": '#include "io/atomic_file.h"',
                     "view/frame.h": '#include "app/commands.h"',
                     "live/live_session.cpp": '#include "python/scene_handle.h"',
                     "python/module.cpp": '#include "app/commands.h"'}
            for name, line in cases.items():
                target = copy / name
                original = target.read_text()
                target.write_text(line + "\n" + original)
                if not problems(copy):
                    print(f"FAIL: the rules let {name} have {line}")
                    found.append(name)
                target.write_text(original)
            if args.tests:
                tests = pathlib.Path(tmp) / "tests"
                shutil.copytree(args.tests, tests)
                for name, line in {"core/energy_test.cpp": '#include "scene/build_model.h"',
                                   "run/table_run_test.cpp": '#include "../core/text_support.h"',
                                   "live/control_test.cpp": '#include "app/commands.h"'}.items():
                    target = tests / name
                    target.write_text(line + "\n" + target.read_text())
                    if not test_problems(tests):
                        print(f"FAIL: the rules let tests/{name} have {line}")
                        found.append(name)
    print(f"{'FAIL' if found else 'ok'}: the includes of {args.src} against the layers")
    return 1 if found else 0


if __name__ == "__main__":
    sys.exit(main())
