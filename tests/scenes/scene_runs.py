"""What the scene tests share: `cablefilm run` of a scene into a folder, and a CSV it wrote."""
import csv
import io
import subprocess


def run(cablefilm, scene, out, timeout=600):
    """Runs `cablefilm run SCENE --no-film --out OUT`; exits the test, naming the scene and the
    end of cablefilm's stderr, when it fails."""
    done = subprocess.run([cablefilm, "run", str(scene), "--no-film", "--out", str(out)],
                          capture_output=True, text=True, timeout=timeout)
    if done.returncode != 0:
        raise SystemExit(f"FAIL: {scene.name}: exit {done.returncode}: {done.stderr[-600:]}")


def table(path):
    """The rows of a CSV file as dicts of its header's names."""
    return list(csv.DictReader(io.StringIO(path.read_text())))


def report(failures):
    """Prints each failure and the verdict; the test's exit status."""
    for f in failures:
        print("FAIL:", f)
    print("FAIL" if failures else "ok")
    return 1 if failures else 0
