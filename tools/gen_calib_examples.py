#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Generate the example measurements of "Calibrating a brake" (README).

    /usr/bin/python3 tools/gen_calib_examples.py [--out docs/examples]

Synthetic, written by this project (fixed seed, so the files are the same on
every run), for a made-up brake "example" whose true parameters are TRUTH:

  dyno.csv      a brake-dynamometer run: disc_rpm,torque_nm,pressure_bar;
                14 speeds x 3 line pressures, pad radius 0.12 m, piston area
                2000 mm^2 per face, 2 faces; torque with 1.5 % noise,
                pressure with 0.2 bar noise (what a dyno log looks like)
  tap_test.wav  a tap test: the pad's acceleration ring-down after a hammer
                impulse, 48 kHz mono 16 bit, 5 ms pre-trigger, 0.1 s, noise
                1 % of the peak
  frf.csv       a measured receptance f_hz,magnitude,phase_deg [m/N, deg]
                around the pad mode, 2 % complex noise
"""

import math
import os
import sys
import wave

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("numpy")
import helptext  # noqa: E402
import numpy as np  # noqa: E402

SEED = 20261129
TRUTH = {
    "mu_inf": 0.28, "delta_mu": 0.12, "slope_spm": 2.5,          # friction law
    "omega0_radps": 5600.0, "damping": 0.03, "mass_kg": 0.9,     # pad mode
}
PAD_RADIUS_M = 0.12
PISTON_AREA_MM2 = 2000.0
FACES = 2
RATE_HZ = 48000


def mu_of_v(v):
    return TRUTH["mu_inf"] + TRUTH["delta_mu"] * np.exp(-TRUTH["slope_spm"] * v)


def dyno(rng):
    rpm = np.round(np.geomspace(5.0, 600.0, 14), 1)
    rows = []
    for p_bar in (15.0, 25.0, 40.0):
        for r in rpm:
            v = r * 2.0 * math.pi / 60.0 * PAD_RADIUS_M
            normal_n = FACES * p_bar * 1e5 * PISTON_AREA_MM2 * 1e-6
            torque = mu_of_v(v) * normal_n * PAD_RADIUS_M * (1.0 + 0.015 * rng.standard_normal())
            p_meas = p_bar + 0.2 * rng.standard_normal()
            rows.append((r, torque, p_meas))
    return rows


def ring_down(rng, n, rate_hz, pre_s=0.005, noise=0.01):
    """Acceleration after a unit impulse at t = pre_s, plus white noise."""
    w0, d = TRUTH["omega0_radps"], TRUTH["damping"]
    sig = d * w0
    wd = w0 * math.sqrt(1.0 - d * d)
    t = np.arange(n) / rate_hz
    tau = np.clip(t - pre_s, 0.0, None)
    x = np.exp(-sig * tau) * np.sin(wd * tau) / wd
    xd = np.exp(-sig * tau) * (np.cos(wd * tau) - sig / wd * np.sin(wd * tau))
    acc = np.where(t >= pre_s, -2.0 * sig * xd - w0 * w0 * x, 0.0)
    acc = acc / np.max(np.abs(acc))
    return t, acc + noise * rng.standard_normal(n)


def frf(rng):
    w0, d, m = TRUTH["omega0_radps"], TRUTH["damping"], TRUTH["mass_kg"]
    f = np.linspace(600.0, 1200.0, 241)
    w = 2.0 * math.pi * f
    h = 1.0 / (m * (w0 * w0 - w * w + 2j * d * w0 * w))
    h = h * (1.0 + 0.02 * (rng.standard_normal(len(f)) + 1j * rng.standard_normal(len(f))))
    return f, np.abs(h), np.degrees(np.angle(h))


def write_wav(path, samples, rate_hz):
    pcm = np.round(samples / np.max(np.abs(samples)) * 0.7 * 32767).astype("<i2")
    with wave.open(path, "wb") as w:
        w.setnchannels(1)
        w.setsampwidth(2)
        w.setframerate(rate_hz)
        w.writeframes(pcm.tobytes())


def main(argv):
    ap = helptext.parser(__doc__, "tools/gen_calib_examples.py")
    ap.add_argument("--out", default="docs/examples", metavar="DIR",
                    help="folder the three files are written to (default docs/examples)")
    args = ap.parse_args(argv)
    try:
        os.makedirs(args.out, exist_ok=True)
    except OSError as e:
        sys.exit("gen_calib_examples.py: --out %s: %s" % (args.out, e.strerror))
    rng = np.random.default_rng(SEED)
    with open(os.path.join(args.out, "dyno.csv"), "w", encoding="ascii") as f:
        f.write("# brake dynamometer run (synthetic, tools/gen_calib_examples.py): "
                f"pad radius {PAD_RADIUS_M} m, piston area {PISTON_AREA_MM2:g} mm^2 "
                f"per face, {FACES} faces\n")
        f.write("disc_rpm,torque_nm,pressure_bar\n")
        for r, tq, p in dyno(rng):
            f.write(f"{r:.1f},{tq:.2f},{p:.2f}\n")
    _, acc = ring_down(rng, int(0.1 * RATE_HZ), RATE_HZ)
    write_wav(os.path.join(args.out, "tap_test.wav"), acc, RATE_HZ)
    fq, mag, ph = frf(rng)
    with open(os.path.join(args.out, "frf.csv"), "w", encoding="ascii") as f:
        f.write("# receptance of the pad mode (synthetic, tools/gen_calib_examples.py), m/N\n")
        f.write("f_hz,magnitude,phase_deg\n")
        for a, b, c in zip(fq, mag, ph):
            f.write(f"{a:.2f},{b:.6e},{c:.3f}\n")
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
