#!/usr/bin/env python3
"""Issue 12: cablefilm installed, packaged and used downstream, from an already-built tree.

  install_test.py run      --build-dir B --source-dir S   cmake --install into a temporary
        prefix; the installed `cablefilm` (found on PATH) runs a shortened case P63 from another
        folder with the source and build trees hidden (an empty tmpfs mounted over them in a
        private mount namespace, when this runs as root), and writes the film and the results
        the build tree's program writes; the installed Python module (when built), imported
        through PYTHONPATH under the prefix, gives the doubles of the build tree's results.nc.
        The example scenes (share/cablefilm/scenes) and the manual (share/doc/cablefilm) are
        installed, and an installed scene that reads a motion table passes `cablefilm check`.
  install_test.py deb      ...   cpack -G DEB: the .deb's contents (the Python module, the
        example scenes and the manual too), its Debian dependencies, and its program run from
        the unpacked package.
  install_test.py consumer ...   tests/install/consumer configured against the temporary
        prefix with find_package(cablefilm), linked to cablefilm::core, run.
"""
import argparse
import os
import re
import shutil
import subprocess
import sys
import tempfile

P63_ROWS_PER_SECOND = 30  # [output] interval defaults to one row per film frame (speed / fps)


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def run(cmd, **kwargs):
    print("$ " + " ".join(cmd), flush=True)
    result = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True,
                            **kwargs)
    if result.returncode != 0:
        print(result.stdout)
        fail("%s exited with %d" % (cmd[0], result.returncode))
    return result.stdout


def install(build_dir, prefix):
    run(["cmake", "--install", build_dir, "--prefix", prefix])
    for path in ["bin/cablefilm", "lib/libcablefilm_core.a",
                 "include/cablefilm/core/line_equilibrium.h",
                 "lib/cmake/cablefilm/cablefilmConfig.cmake",
                 "lib/cmake/cablefilm/cablefilmConfigVersion.cmake",
                 "lib/cmake/cablefilm/cablefilmTargets.cmake",
                 "share/cablefilm/scenes/polachek1963.toml",
                 "share/cablefilm/scenes/ship_table.toml", "share/cablefilm/scenes/ship_motion.csv",
                 "share/doc/cablefilm/README.md", "share/doc/cablefilm/scene-format.md",
                 "share/doc/cablefilm/recipes/towed_cable.toml"]:
        if not os.path.isfile(os.path.join(prefix, path)):
            fail("cmake --install left no " + path)
    print("installed into " + prefix)


def can_hide_trees():
    """True when this process may mount over folders in a mount namespace of its own."""
    probe = tempfile.mkdtemp(prefix="cablefilm_ns_probe_")
    try:
        return subprocess.run(["unshare", "--mount", "--propagation", "private", "--",
                               "mount", "-t", "tmpfs", "none", probe],
                              stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL).returncode == 0
    except OSError:
        return False
    finally:
        os.rmdir(probe)


def read_rows(path):
    with open(path) as f:
        lines = f.read().splitlines()
    return lines[0], [line.split(",") for line in lines[1:]]


def built_module(build):
    """The Python module of the build tree (<build>/python/cablefilm.*.so), or None."""
    folder = os.path.join(build, "python")
    names = [n for n in os.listdir(folder) if n.startswith("cablefilm.") and n.endswith(".so")] \
        if os.path.isdir(folder) else []
    return names[0] if names else None


# Run by the interpreter of the installed module, in the folder of test_run's scene: the module
# found through PYTHONPATH under the prefix, the same doubles as the build tree's results.nc.
MODULE_CHECK = """
import sys, numpy, netCDF4, cablefilm
prefix = sys.argv[1]
if not cablefilm.__file__.startswith(prefix):
    sys.exit("cablefilm imported from %s, not from the prefix" % cablefilm.__file__)
result = cablefilm.run("p63.toml")
with netCDF4.Dataset("ref/results.nc") as ds:
    for name in ["time", "x", "y", "z", "tension"]:
        if not numpy.array_equal(getattr(result, name), ds.variables[name][:].data):
            sys.exit("the installed module's %s differs from results.nc" % name)
print("installed module %s: %d rows, peak %.6g N, the doubles of results.nc"
      % (cablefilm.__file__, len(result.time), result.peak_tension))
"""


def test_run(args):
    source, build = os.path.realpath(args.source_dir), os.path.realpath(args.build_dir)
    tmp = tempfile.mkdtemp(prefix="cablefilm_install_run_")
    try:
        prefix = os.path.join(tmp, "prefix")
        install(build, prefix)
        binary = os.path.join(prefix, "bin", "cablefilm")
        # The renderer once read its shaders through the source path compiled in.
        with open(binary, "rb") as f:
            if os.path.join(source, "shaders").encode() in f.read():
                fail("the installed program names the source shaders folder")
        work = os.path.join(tmp, "x")  # another folder: no scene, shader or page beside it
        os.makedirs(work)
        duration = 10.0
        with open(os.path.join(source, "scenes", "polachek1963.toml")) as f:
            scene = f.read()
        if "duration = 60.0" not in scene:
            fail("scenes/polachek1963.toml no longer says duration = 60.0")
        with open(os.path.join(work, "p63.toml"), "w") as f:
            f.write(scene.replace("duration = 60.0", "duration = %g" % duration))

        env = dict(os.environ)
        env.pop("CABLEFILM_SHADERS", None)
        env["PATH"] = os.path.join(prefix, "bin") + os.pathsep + env.get("PATH", "")
        command = ["cablefilm", "run", "p63.toml", "--out", "out", "--size", "320x180"]
        hidden = [source] + ([build] if not build.startswith(source + os.sep) else [])
        if can_hide_trees():
            # An empty, read-only tmpfs over each tree, then the program, in one private
            # mount namespace: the trees are not there for it (checked first).
            script = ('for d in "$@"; do [ "$d" = -- ] && break; '
                      'mount -t tmpfs -o size=1m,mode=0555 none "$d" || exit 97; '
                      '[ -e "$d/shaders" ] && exit 98; done; '
                      'while [ "$1" != -- ]; do shift; done; shift; exec "$@"')
            command = (["unshare", "--mount", "--propagation", "private", "--", "sh", "-c",
                        script, "sh"] + hidden + ["--"] + command)
            print("source tree hidden from the program: " + ", ".join(hidden))
        else:
            print("NOTE: cannot mount in a namespace of our own (not root?): the source tree "
                  "stays visible, the program runs from " + work)
        out = run(command, cwd=work, env=env)
        print(out)
        if "peak tension" not in out:
            fail("the run printed no peak tension")

        results = os.path.join(work, "out")
        for name in ["film.mp4", "timeseries.csv", "equilibrium.csv", "max_tension.png"]:
            if not os.path.isfile(os.path.join(results, name)):
                fail("the installed program wrote no " + name)
        with open(os.path.join(results, "film.mp4"), "rb") as f:
            film = f.read()
        if film[4:8] != b"ftyp" or b"moov" not in film or b"avc1" not in film:
            fail("film.mp4 is not an H.264 MP4")
        header, rows = read_rows(os.path.join(results, "timeseries.csv"))
        if header != ("t,x_end,y_end,z_end,tension_start,tension_end,tension_max,link_max"
                      ",fx_start,fy_start,fz_start,fx_end,fy_end,fz_end,angle_start,angle_end"):
            fail("timeseries.csv header " + header)
        expected = int(round(duration * P63_ROWS_PER_SECOND)) + 1
        if len(rows) != expected:
            fail("timeseries.csv has %d rows, expected %d" % (len(rows), expected))
        times = [float(r[0]) for r in rows]
        if times[0] != 0 or abs(times[-1] - duration) > 1e-9 or \
                any(b <= a for a, b in zip(times, times[1:])):
            fail("timeseries.csv times do not run from 0 to %g" % duration)
        _, stations = read_rows(os.path.join(results, "equilibrium.csv"))
        if len(stations) != 61:
            fail("equilibrium.csv has %d stations, expected 61" % len(stations))
        peak = max(float(r[6]) for r in rows)
        print("timeseries.csv: %d rows, t = 0 to %g s, peak tension_max %.1f N; film.mp4 %d bytes"
              % (len(rows), times[-1], peak, len(film)))

        # The same numbers as the build tree's program.
        run([os.path.join(build, "cablefilm"), "run", "p63.toml", "--out", "ref", "--no-film"],
            cwd=work)
        for name in ["timeseries.csv", "equilibrium.csv"]:
            with open(os.path.join(results, name)) as a, \
                    open(os.path.join(work, "ref", name)) as b:
                if a.read() != b.read():
                    fail(name + " differs from the build tree's program")
        # The installed example scenes run as installed: a motion table's `file` is found
        # beside its scene.
        installed_scene = os.path.join(prefix, "share", "cablefilm", "scenes", "ship_table.toml")
        if "ok" not in run(["cablefilm", "check", installed_scene], cwd=work, env=env):
            fail("cablefilm check of the installed " + installed_scene + " printed no ok")
        version = run(["cablefilm", "--version"], env=env).strip()
        if not re.match(r"^cablefilm \d+\.\d+", version):
            fail("--version printed " + version)
        print(version)

        module = built_module(build)
        if module:  # the Python module, installed beside the program
            lib = os.path.join(prefix, "lib")
            found = [os.path.join(lib, v, p, module) for v in os.listdir(lib)
                     if v.startswith("python3") for p in ("dist-packages", "site-packages")
                     if os.path.isfile(os.path.join(lib, v, p, module))]
            if len(found) != 1:
                fail("cmake --install put %s under %s/lib/python3*: %s" % (module, prefix, found))
            env["PYTHONPATH"] = os.path.dirname(found[0])
            command = [sys.executable, "-c", MODULE_CHECK, prefix]
            if can_hide_trees():
                command = (["unshare", "--mount", "--propagation", "private", "--", "sh", "-c",
                            script, "sh"] + hidden + ["--"] + command)
            print(run(command, cwd=work, env=env))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("PASS")


def test_deb(args):
    build = os.path.realpath(args.build_dir)
    tmp = tempfile.mkdtemp(prefix="cablefilm_install_deb_")
    try:
        run(["cpack", "-G", "DEB", "--config", os.path.join(build, "CPackConfig.cmake"),
             "-B", tmp])
        debs = [f for f in os.listdir(tmp) if f.endswith(".deb")]
        if len(debs) != 1:
            fail("cpack made %s" % debs)
        deb = os.path.join(tmp, debs[0])
        listing = run(["dpkg-deb", "-c", deb])
        print(listing)
        paths = [line.split()[-1] for line in listing.splitlines() if line.strip()]
        for want in ["./usr/bin/cablefilm", "./usr/lib/libcablefilm_core.a",
                     "./usr/include/cablefilm/core/line_equilibrium.h",
                     "./usr/lib/cmake/cablefilm/cablefilmConfig.cmake",
                     "./usr/lib/cmake/cablefilm/cablefilmConfigVersion.cmake",
                     "./usr/lib/cmake/cablefilm/cablefilmTargets.cmake",
                     "./usr/share/cablefilm/scenes/polachek1963.toml",
                     "./usr/share/doc/cablefilm/scene-format.md"]:
            if want not in paths:
                fail(debs[0] + " has no " + want)
        module = built_module(build)
        if module and not any(p.startswith("./usr/lib/python3") and p.endswith("/" + module)
                              for p in paths):
            fail(debs[0] + " has no Python module " + module + " under ./usr/lib/python3*")
        if any("shaders" in p or (p.startswith("./usr/share/cablefilm/")
                                   and p != "./usr/share/cablefilm/"
                                   and not p.startswith("./usr/share/cablefilm/scenes/"))
               for p in paths):
            fail("the .deb ships shader files: they belong inside the program")
        depends = run(["dpkg-deb", "-f", deb, "Depends"]).strip()
        print("Depends: " + depends)
        names = [re.split(r"[ (]", alt.strip())[0]
                 for dep in depends.split(",") for alt in dep.split("|")]
        for want in ["libosmesa6", "libavcodec59", "libjpeg62-turbo", "fonts-dejavu-core"]:
            if want not in names:
                fail("Depends lacks " + want)
        for name in names:  # every one a Debian package this machine knows
            if subprocess.run(["dpkg-query", "-W", name], stdout=subprocess.DEVNULL,
                              stderr=subprocess.DEVNULL).returncode != 0:
                fail("Depends names %s, which is no installed Debian package" % name)
        unpacked = os.path.join(tmp, "root")
        run(["dpkg-deb", "-x", deb, unpacked])
        version = run([os.path.join(unpacked, "usr", "bin", "cablefilm"), "--version"]).strip()
        print("%s: %d bytes, %d entries; unpacked program: %s"
              % (debs[0], os.path.getsize(deb), len(paths), version))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("PASS")


def test_consumer(args):
    source, build = os.path.realpath(args.source_dir), os.path.realpath(args.build_dir)
    tmp = tempfile.mkdtemp(prefix="cablefilm_install_consumer_")
    try:
        prefix = os.path.join(tmp, "prefix")
        install(build, prefix)
        consumer = os.path.join(tmp, "consumer")
        shutil.copytree(os.path.join(source, "tests", "install", "consumer"), consumer)
        out = run(["cmake", "-S", consumer, "-B", os.path.join(consumer, "build"), "-G", "Ninja",
                   "-DCMAKE_BUILD_TYPE=Release", "-DCMAKE_PREFIX_PATH=" + prefix,
                   "-DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF"])
        found = re.search(r"cablefilm (\S+) from (\S+), includes (\S+)", out)
        if not found:
            print(out)
            fail("the consumer did not report what it found")
        print(found.group(0))
        for path in found.group(2, 3):
            if not os.path.realpath(path).startswith(os.path.realpath(prefix)):
                fail("the consumer found cablefilm outside the prefix: " + path)
        run(["cmake", "--build", os.path.join(consumer, "build")])
        print(run([os.path.join(consumer, "build", "hanging_chain")]))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    print("PASS")


def main():
    parser = argparse.ArgumentParser(description=__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("test", choices=["run", "deb", "consumer"])
    parser.add_argument("--build-dir", required=True)
    parser.add_argument("--source-dir", required=True)
    args = parser.parse_args()
    {"run": test_run, "deb": test_deb, "consumer": test_consumer}[args.test](args)


if __name__ == "__main__":
    main()
