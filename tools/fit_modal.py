#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Identify the pad/caliper mode (w0, D) from a tap test or a measured FRF.

    tools/fit_modal.py DATA.(csv|wav) [--mass-kg M [--mass-sd-kg S]] [--json]
                       [-o FILE.cal [--base FILE.cal]] [--plot FILE.png]

DATA:
  t_s,accel  or  t_s,displacement   a ring-down (free decay after a tap),
                                     uniformly sampled; any unit
  FILE.wav                           the same as a WAV recording (first channel)
  f_hz,magnitude,phase_deg           a measured frequency response; --frf says
                                     which kind (receptance, the default,
                                     mobility or accelerance)

Ring-down: the damped frequency from the spectral peak (Hann window, zero
padding, parabolic refinement), the decay rate from the log decrement of the
Hilbert envelope; both refined by a least-squares damped-sine fit
e^(-sig t) (A cos wd t + B sin wd t) + c from the envelope's maximum on,
whose covariance (scaled by the residuals) gives the uncertainties. Then
w0 = sqrt(wd^2 + sig^2) = wd / sqrt(1 - D^2) and D = sig / w0.
Frequency response: half-power bandwidth for a first estimate, refined by a
least-squares fit of the complex single-mode receptance g / (w0^2 - w^2 +
2 i D w0 w) to the real and imaginary parts (the least-squares form of a
circle fit: the model's Nyquist plot is the circle).

--json prints {"omega0_radps": {"value", "stderr", "ci95": [lo, hi]},
"damping": {...}, "corr_omega0_damping", "rms"} (and "mass_kg" with
--mass-kg). -o writes omega0_radps, damping, omega0_radps_sd, damping_sd
(and mass_kg, mass_kg_sd with --mass-kg); --base keeps the other lines of a
calibration file; --no-sd leaves the standard deviations out.
Bad data get one line and exit status 1.
"""

import math
import os
import sys
import warnings

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import deps  # noqa: E402  (names the Debian package of a missing module)

deps.need("numpy", "scipy")
import numpy as np  # noqa: E402
from scipy.optimize import OptimizeWarning, curve_fit  # noqa: E402
from scipy.signal import hilbert  # noqa: E402

import calibfit as cf  # noqa: E402
import helptext  # noqa: E402

MIN_SAMPLES = 64
OMEGA0_MAX = 500000.0
TIME_LAYOUTS = {
    "accel": (("t_s", "accel"), ()),
    "displacement": (("t_s", "displacement"), ()),
}
FRF_LAYOUT = {"frf": (("f_hz", "magnitude", "phase_deg"), ())}
COMMENTS = {
    "omega0_radps": "fitted: natural angular frequency w0 [rad/s]",
    "damping": "fitted: damping ratio D",
    "mass_kg": "measured: moving mass of pad and caliper [kg]",
    "omega0_radps_sd": "fitted: standard deviation of omega0_radps [rad/s]",
    "damping_sd": "fitted: standard deviation of damping",
    "mass_kg_sd": "measured: standard deviation of mass_kg [kg]",
}


def modal_from(wd, sig, cov_wd_sig):
    """(w0, D) and their covariance from the damped frequency and decay rate."""
    w0 = math.hypot(wd, sig)
    d = sig / w0
    jac = np.array([[wd / w0, sig / w0],
                    [-sig * wd / w0 ** 3, wd * wd / w0 ** 3]])
    return np.array([w0, d]), jac @ cov_wd_sig @ jac.T


def damped(t, a, b, wd, sig, c):
    e = np.exp(-sig * t)
    return e * (a * np.cos(wd * t) + b * np.sin(wd * t)) + c


def spectral_peak(y, rate_hz):
    """Damped angular frequency of the strongest spectral line [rad/s]."""
    n = len(y)
    nfft = 8 * (1 << int(math.ceil(math.log2(n))))
    spec = np.abs(np.fft.rfft((y - np.mean(y)) * np.hanning(n), nfft))
    k = int(np.argmax(spec[1:])) + 1
    if k >= len(spec) - 1 or spec[k] <= 0:
        raise cf.Refusal("no oscillation found (the spectrum peaks at the Nyquist frequency)")
    lm, l0, lp = np.log(spec[k - 1:k + 2] + 1e-300)
    den = lm - 2 * l0 + lp
    shift = 0.5 * (lm - lp) / den if den < 0 else 0.0
    return 2.0 * math.pi * (k + shift) * rate_hz / nfft


def log_decrement(env, rate_hz):
    """Decay rate [1/s] from a straight line through ln(envelope), taken
    while the envelope is above three times the noise floor and 2 % of its
    maximum. None when that is under a handful of samples."""
    floor = float(np.median(env[-max(len(env) // 5, 1):]))
    limit = max(3.0 * floor, 0.02 * float(env[0]))
    below = np.nonzero(env < limit)[0]
    end = int(below[0]) if len(below) else len(env)
    if end < 8:
        return None, end
    t = np.arange(end) / rate_hz
    slope = np.polyfit(t, np.log(env[:end]), 1)[0]
    return -slope, end


def ring_down(t, y):
    """Fit a ring-down. Returns a result dict (value [w0, D], cov, dof, rms,
    and what the plot needs). Raises cf.Refusal."""
    n = len(y)
    if n < MIN_SAMPLES:
        raise cf.Refusal(f"{n} samples: a ring-down needs at least {MIN_SAMPLES}")
    dt = np.diff(t)
    if np.any(dt <= 0):
        raise cf.Refusal("t_s must increase from row to row")
    step = float(np.median(dt))
    if np.max(np.abs(dt - step)) > 1e-3 * step:
        raise cf.Refusal("the samples are not uniformly spaced in time")
    rate_hz = 1.0 / step
    if np.ptp(y) == 0:
        raise cf.Refusal("the signal is constant: nothing rings")
    env_all = np.abs(hilbert(y - np.median(y)))
    start = int(np.argmax(env_all))
    tt = t[start:] - t[start]
    yy = y[start:]
    if len(yy) < MIN_SAMPLES:
        raise cf.Refusal("the ring-down after the tap is shorter than "
                         f"{MIN_SAMPLES} samples")
    wd0 = spectral_peak(yy, rate_hz)
    sig_ld, end = log_decrement(env_all[start:], rate_hz)
    sig0 = sig_ld if (sig_ld is not None and sig_ld > 0) else 0.01 * wd0
    e = np.exp(-sig0 * tt)
    basis = np.column_stack([e * np.cos(wd0 * tt), e * np.sin(wd0 * tt), np.ones_like(tt)])
    ab, *_ = np.linalg.lstsq(basis, yy, rcond=None)
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore", OptimizeWarning)
            p, cov = curve_fit(damped, tt, yy, p0=[ab[0], ab[1], wd0, sig0, ab[2]],
                               maxfev=4000)
    except (RuntimeError, ValueError):
        raise cf.Refusal("the damped-sine fit did not converge: is this a "
                         "single-mode ring-down?") from None
    if not np.all(np.isfinite(cov)):
        raise cf.Refusal("the record does not determine frequency and damping")
    wd, sig = abs(p[2]), p[3]
    if sig <= 0:
        raise cf.Refusal("the record does not decay: no damping can be measured")
    value, vcov = modal_from(wd, sig, cov[2:4, 2:4])
    res = {"value": value, "cov": vcov, "dof": len(yy) - 5,
           "rms": float(np.sqrt(np.mean((yy - damped(tt, *p)) ** 2))),
           "estimates": {"spectral_peak_wd_radps": wd0, "log_decrement_sigma_1ps": sig_ld},
           "plot": ("ringdown", t, y, t[start], p)}
    check(res)
    return res


def receptance(f_hz, mag, phase_deg, kind):
    w = 2.0 * math.pi * f_hz
    h = mag * np.exp(1j * np.radians(phase_deg))
    if kind == "mobility":
        h = h / (1j * w)
    elif kind == "accelerance":
        h = h / (-(w * w))
    return w, h


def sdof(w, w0, d, g):
    return g / (w0 * w0 - w * w + 2j * d * w0 * w)


def half_power(w, h):
    """(w_peak, D, g) from the half-power bandwidth of |h|."""
    mag = np.abs(h)
    k = int(np.argmax(mag))
    half = mag[k] / math.sqrt(2.0)
    lo = np.nonzero(mag[:k] < half)[0]
    hi = np.nonzero(mag[k:] < half)[0]
    if k == 0 or k == len(mag) - 1 or not len(lo) or not len(hi):
        raise cf.Refusal("the response does not contain the peak and both half-power "
                         "points: measure a wider band around the mode")
    i, j = int(lo[-1]), int(hi[0]) + k
    w1 = np.interp(half, [mag[i], mag[i + 1]], [w[i], w[i + 1]])
    w2 = np.interp(half, [mag[j], mag[j - 1]], [w[j], w[j - 1]])
    d = (w2 - w1) / (2.0 * w[k])
    return w[k], d, mag[k] * 2.0 * d * w[k] ** 2


def frf(f_hz, mag, phase_deg, kind):
    n = len(f_hz)
    if n < 8:
        raise cf.Refusal(f"{n} frequencies: a frequency response needs at least 8")
    if np.any(np.diff(f_hz) <= 0) or f_hz[0] <= 0:
        raise cf.Refusal("f_hz must be positive and increase from row to row")
    if np.any(mag <= 0):
        raise cf.Refusal("magnitude must be positive in every row")
    w, h = receptance(f_hz, mag, phase_deg, kind)
    wp, dp, gp = half_power(w, h)
    scale = np.abs(h)

    def stacked(wv, w0, d, g):
        m = sdof(wv, w0, d, g) / scale
        return np.concatenate([m.real, m.imag])

    target = np.concatenate([(h / scale).real, (h / scale).imag])
    sign = 1.0 if np.real(h[0]) * (w[0] < wp) >= 0 else -1.0
    try:
        with warnings.catch_warnings(), np.errstate(all="ignore"):
            warnings.simplefilter("ignore", OptimizeWarning)
            p, cov = curve_fit(stacked, w, target, p0=[wp, dp, sign * gp], maxfev=4000)
    except (RuntimeError, ValueError):
        raise cf.Refusal("the single-mode fit did not converge") from None
    if not np.all(np.isfinite(cov)):
        raise cf.Refusal("the response does not determine frequency and damping")
    p[1] = abs(p[1])
    res = {"value": np.array([abs(p[0]), p[1]]), "cov": cov[:2, :2], "dof": 2 * n - 3,
           "rms": float(np.sqrt(np.mean((target - stacked(w, *p)) ** 2))),
           "estimates": {"half_power_omega0_radps": wp, "half_power_damping": dp},
           "plot": ("frf", w, h, p)}
    check(res)
    return res


def check(res):
    w0, d = res["value"]
    q = cf.t_quantile(res["dof"])
    sd = np.sqrt(np.diag(res["cov"]))
    if not 0.0 < d < 1.0:
        raise cf.Refusal(f"damping ratio {d:.3g}: not an underdamped mode")
    if 2.0 * q * sd[1] > d:
        raise cf.Refusal(f"the damping is not identified: its 95 % interval "
                         f"[{d - q * sd[1]:.3g}, {d + q * sd[1]:.3g}] is wider than its value")
    if not 0.0 < w0 <= OMEGA0_MAX:
        raise cf.Refusal(f"omega0 {w0:.6g} rad/s is outside the calibration's range "
                         f"0 .. {OMEGA0_MAX:g}")


def summary(res, mass=None):
    q = cf.t_quantile(res["dof"])
    sd = np.sqrt(np.diag(res["cov"]))
    out = {"omega0_radps": cf.param_json(res["value"][0], sd[0], q),
           "damping": cf.param_json(res["value"][1], sd[1], q),
           "corr_omega0_damping": float(res["cov"][0, 1] / (sd[0] * sd[1])),
           "rms": res["rms"]}
    if mass is not None:
        out["mass_kg"] = cf.param_json(mass[0], mass[1], cf.t_quantile(None))
    return out


def read_wav(path):
    from scipy.io import wavfile

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            rate, data = wavfile.read(path)
    except (ValueError, EOFError) as e:
        raise cf.Refusal(f"{path}: not a readable WAV file ({e})") from None
    data = np.asarray(data, dtype=float)
    if data.ndim > 1:
        data = data[:, 0]
    if data.size == 0:
        raise cf.Refusal(f"{path}: empty WAV file (no samples)")
    if not np.all(np.isfinite(data)):
        raise cf.Refusal(f"{path}: samples that are not finite numbers")
    return np.arange(len(data)) / float(rate), data


def plot(path, res, title):
    plt = cf.pyplot()

    s = summary(res)
    w0, w0_sd = s["omega0_radps"]["value"], s["omega0_radps"]["stderr"]
    # an NVH engineer reads the mode in Hz; the calibration keeps rad/s
    label = (f"f0 = {w0 / (2 * math.pi):.1f} ± {w0_sd / (2 * math.pi):.2g} Hz "
             f"(ω0 = {w0:.1f} ± {w0_sd:.2g} rad/s), "
             f"D = {s['damping']['value']:.4f} ± {s['damping']['stderr']:.2g}")
    kind = res["plot"][0]
    if kind == "ringdown":
        _, t, y, t0, p = res["plot"]
        fig, ax = plt.subplots(figsize=(7.5, 4.5))
        ax.plot(t * 1e3, y, color="0.6", lw=0.8, label="measured")
        tt = t[t >= t0] - t0
        ax.plot((tt + t0) * 1e3, damped(tt, *p), color="tab:blue", lw=0.8,
                label="damped-sine fit:\n" + label)
        env = math.hypot(p[0], p[1]) * np.exp(-p[3] * tt)
        ax.plot((tt + t0) * 1e3, p[4] + env, "--", color="tab:red", lw=1,
                label="envelope e^(-D ω0 t)")
        ax.plot((tt + t0) * 1e3, p[4] - env, "--", color="tab:red", lw=1)
        ax.set_xlabel("time [ms]")
        ax.set_ylabel("signal [sample value, as recorded]")
    else:
        _, w, h, p = res["plot"]
        # mobility and accelerance are converted to receptance (SI input: m/N)
        unit = "[m/N]"
        fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.8))
        ax.semilogy(w / (2 * math.pi), np.abs(h), ".", color="0.4", ms=3, label="measured")
        ax.semilogy(w / (2 * math.pi), np.abs(sdof(w, *p)), color="tab:blue",
                    label="single-mode fit:\n" + label)
        ax.set_xlabel("frequency [Hz]")
        ax.set_ylabel("receptance |H| %s" % unit)
        ax2.plot(h.real, h.imag, ".", color="0.4", ms=3, label="measured")
        m = sdof(w, *p)
        ax2.plot(m.real, m.imag, color="tab:blue", label="single-mode fit (a circle)")
        ax2.set_aspect("equal", "datalim")
        ax2.set_title("Nyquist plot", fontsize=9)
        ax2.set_xlabel("Re H %s" % unit)
        ax2.set_ylabel("Im H %s" % unit)
        ax2.legend(fontsize=7)
        ax2.grid(alpha=0.3)
    cf.finish_plot(fig, ax, title, path)


def analyse(path, kind):
    if path.lower().endswith(".wav"):
        t, y = read_wav(path)
        return ring_down(t, y)
    layout, cols = cf.read_csv(path, {**TIME_LAYOUTS, **FRF_LAYOUT})
    if layout == "frf":
        return frf(cols["f_hz"], cols["magnitude"], cols["phase_deg"], kind)
    return ring_down(cols["t_s"], cols[layout])


def main(argv):
    ap = helptext.parser(__doc__, "tools/fit_modal.py")
    ap.add_argument("data", metavar="DATA", help="a ring-down CSV, a WAV recording or an FRF CSV (below)")
    ap.add_argument("--frf", choices=("receptance", "mobility", "accelerance"),
                    default="receptance", help="kind of a measured frequency response")
    ap.add_argument("--mass-kg", type=float, metavar="M", help="moving mass of pad and caliper (weighed)")
    ap.add_argument("--mass-sd-kg", type=float, default=0.0, metavar="S",
                    help="its standard deviation (default 0)")
    cf.add_output_args(ap, "PNG of the data and the fit")
    args = ap.parse_args(argv)
    mass = None
    if args.mass_kg is not None:
        if not (0.0 < args.mass_kg <= 10000.0) or not (0.0 <= args.mass_sd_kg <= args.mass_kg):
            raise cf.Refusal("--mass-kg must be in (0, 10000] and --mass-sd-kg in [0, mass]")
        mass = (args.mass_kg, args.mass_sd_kg)
    try:
        res = analyse(args.data, args.frf)
    except cf.Refusal as e:
        msg = str(e)
        raise cf.Refusal(msg if msg.startswith(args.data) else f"{args.data}: {msg}") from None
    s = summary(res, mass)
    if args.output:
        vals = {"omega0_radps": s["omega0_radps"]["value"], "damping": s["damping"]["value"]}
        if mass:
            vals["mass_kg"] = mass[0]
        if not args.no_sd:
            vals["omega0_radps_sd"] = s["omega0_radps"]["stderr"]
            vals["damping_sd"] = s["damping"]["stderr"]
            if mass:
                vals["mass_kg_sd"] = mass[1]
        cf.write_calib(args.output, vals, COMMENTS, args.base,
                       header=(f"pad mode fitted by tools/fit_modal.py from "
                               f"{os.path.basename(args.data)}",))
    if args.plot:
        plot(args.plot, res, f"pad mode from {os.path.basename(args.data)}")
    if args.json:
        cf.print_json(s)
    elif args.output != "-":
        for k, unit in (("omega0_radps", " rad/s"), ("damping", "")):
            lo, hi = s[k]["ci95"]
            print(f"{k:13s} {s[k]['value']:.6g} +- {s[k]['stderr']:.2g}{unit}"
                  f"  (95 %: {lo:.6g} .. {hi:.6g})")
        print(f"corr(omega0, damping) {s['corr_omega0_damping']:+.3f}; first estimates: " +
              ", ".join(f"{k} {v:.5g}" for k, v in res["estimates"].items() if v is not None))
    return 0


if __name__ == "__main__":
    sys.exit(cf.run_tool(main, sys.argv[1:]))
