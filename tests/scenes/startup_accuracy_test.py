"""Start-up accuracy of the default step control (issue 21, item 1), on case P63 at 60 links.

The independent truth: the explicit scheme (its default safety factor: P63's peak within
0.002 % of the converged run, docs/validation.md) written every 1e-3 s. Its tension carries
millisecond axial ringing that 1/30 s rows alias, so it is low-passed first: zero phase (a
4th-order Butterworth at 5 Hz, below the rows' 15 Hz Nyquist frequency, run forwards and
backwards, as scipy's filtfilt), then read at the default's rows.

- Every row from 0.2 s to 10 s (the start: eq. (3)'s ramp, 5 / nu_s) within 0.1 % of the
  peak: the issue's goal. Measured 0.076 % (0.07 % at 600 links, docs/validation.md).
- Before 0.2 s the filter cannot stand for the truth: the motion reaches the nylon's top link
  after the 25 ms its axial wave takes, a kink the 5 Hz filter spreads back and forth over its
  settling time, 1 / 5 Hz = 0.2 s (the filtered reference differs from the unfiltered there by
  up to 0.18 % of the peak). Those rows are compared with the unfiltered reference instead,
  within 0.15 %: the goal plus the reference's own millisecond ringing, which this comparison
  cannot remove (0.09 % of the peak in 0.1-0.2 s, |unfiltered - filtered| measured here).
  Measured 0.094 %.
- The same run without the start's tolerance (`start_duration = 0`, the step at the 1/30 s
  rows) is off by more than 0.3 % (measured 0.5 % at t = 2.4 s): the test tells the two apart.
"""
import argparse
import cmath
import csv
import io
import math
import pathlib
import re
import subprocess
import sys
import tempfile

DURATION = 12.0      # s: the start (10 s) and 2 s for the filter's end to die out
START_END = 10.0     # s: 5 / nu_s of P63's ramp
FILTER_ONSET = 0.2   # s: rows before it against the unfiltered reference
ONSET_BOUND = 0.15   # % of the peak, for those rows (see above)


def run(cablefilm, scene_text, folder):
    folder.mkdir(parents=True, exist_ok=True)
    scene = folder / "scene.toml"
    scene.write_text(scene_text)
    done = subprocess.run([cablefilm, "run", str(scene), "--no-film", "--out", str(folder)],
                          capture_output=True, text=True, timeout=600)
    if done.returncode != 0:
        raise SystemExit(f"FAIL: {folder.name}: exit {done.returncode}: {done.stderr[-400:]}")
    rows = list(csv.DictReader(io.StringIO((folder / "timeseries.csv").read_text())))
    return [float(r["t"]) for r in rows], [float(r["tension_max"]) for r in rows]


def butterworth_sections(order, cutoff, rate):
    """Second-order sections (b0, b1, b2, a1, a2) of a digital Butterworth low-pass of even
    `order` at `cutoff` Hz for samples at `rate` Hz: the analog prototype's conjugate pole
    pairs, prewarped, through the bilinear transform, each with unit gain at 0 Hz."""
    warped = 2 * rate * math.tan(math.pi * cutoff / rate)  # rad/s
    sections = []
    for k in range(order // 2):
        pole = warped * cmath.exp(1j * math.pi * (2 * k + order + 1) / (2 * order))
        z = (2 * rate + pole) / (2 * rate - pole)   # the bilinear map of the pole
        a1, a2 = -2 * z.real, abs(z) ** 2
        gain = (1 + a1 + a2) / 4                    # unit gain at z = 1
        sections.append((gain, 2 * gain, gain, a1, a2))
    return sections


def filter_once(sections, x):
    y = list(x)
    for b0, b1, b2, a1, a2 in sections:
        s1 = s2 = 0.0  # transposed direct form II, at rest
        out = []
        for v in y:
            w = b0 * v + s1
            s1 = b1 * v - a1 * w + s2
            s2 = b2 * v - a2 * w
            out.append(w)
        y = out
    return y


def zero_phase_lowpass(values, cutoff, rate):
    """Forwards and backwards (zero phase, the squared magnitude). Before t = 0 the line rests
    at its first value, so the forward pass starts at rest on it; the backward pass starts at
    rest on the last value (the 2 s past the compared rows absorb that end)."""
    sections = butterworth_sections(4, cutoff, rate)
    first = values[0]
    forward = [v + first for v in filter_once(sections, [v - first for v in values])]
    last = forward[-1]
    backward = filter_once(sections, [v - last for v in reversed(forward)])
    return [v + last for v in reversed(backward)]


def interpolate(ts, values, t):
    dt = ts[1] - ts[0]
    i = min(len(ts) - 2, max(0, int(t / dt)))
    f = (t - ts[i]) / (ts[i + 1] - ts[i])
    return values[i] + f * (values[i + 1] - values[i])


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--cablefilm", required=True)
    parser.add_argument("--source-dir", required=True, type=pathlib.Path)
    args = parser.parse_args()
    p63 = (args.source_dir / "scenes" / "polachek1963.toml").read_text()
    p63 = re.sub(r"^duration = .*$", f"duration = {DURATION}", p63, flags=re.M)
    p63 = re.sub(r"^film = true", "film = false", p63, flags=re.M)
    reference_scene = p63.replace('time_step = "auto"', 'time_step = "auto"\nintegrator = "explicit"')
    reference_scene = reference_scene.replace("frames = false", "frames = false\ninterval = 0.001")
    old_default = p63.replace('time_step = "auto"', 'time_step = "auto"\nstart_duration = 0')
    failures = []
    with tempfile.TemporaryDirectory() as tmp:
        tmp = pathlib.Path(tmp)
        rt, rT = run(args.cablefilm, reference_scene, tmp / "reference")
        low = zero_phase_lowpass(rT, 5.0, 1.0 / (rt[1] - rt[0]))
        peak = max(low)
        for name, text, bound, want_within in [("default", p63, 0.1, True),
                                               ("start_duration = 0", old_default, 0.3, False)]:
            ts, Ts = run(args.cablefilm, text, tmp / re.sub(r"\W+", "_", name))
            worst, at = 0.0, 0.0
            onset = 0.0
            for t, T in zip(ts, Ts):
                if t > START_END + 1e-9:
                    break
                if t < FILTER_ONSET - 1e-9:
                    onset = max(onset, abs(T - interpolate(rt, rT, t)) / peak * 100)
                    continue
                e = abs(T - interpolate(rt, low, t)) / peak * 100
                if e > worst:
                    worst, at = e, t
            print(f"{name}: rows {FILTER_ONSET}-10 s within {worst:.3f} % of the peak {peak:.1f} N "
                  f"(worst at t = {at:.3f} s); rows before {FILTER_ONSET} s within {onset:.4f} % of the "
                  "unfiltered reference")
            if want_within and worst > bound:
                failures.append(f"{name}: {worst:.3f} % > {bound} % at t = {at:.3f} s")
            if want_within and onset > ONSET_BOUND:
                failures.append(f"{name}: first rows {onset:.4f} % > {ONSET_BOUND} % of the raw reference")
            if not want_within and worst <= bound:
                failures.append(f"{name}: {worst:.3f} % <= {bound} %: the check cannot tell the "
                                "start's tolerance from none")
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
