#!/usr/bin/python3
"""The plain NumPy/SciPy identification docs/performance.md compares `uuvplan identify` with.

    python3 bench/plain_identify.py CAMPAIGN_DIR_OR_CSV

What a user would write in an afternoon for one position-only trial (columns t, force_<dof>,
pos_<dof>): loadtxt, a Savitzky–Golay velocity, the integral least squares of
m·dv/dt = −k·v − kq·v|v| + φ + bias over 1 s intervals (seed 000 eq. 16), its σ from the
residual variance, and a free-run score (the fitted model simulated on the logged force, velocity
MAE). It has none of uuvplan's output-error refinement, outlier handling or coloured-noise
covariance: it is the speed reference, not an accuracy one (bench/position_identify.sh).
Needs python3-numpy and python3-scipy (scripts/install-deps.sh --bench).
"""
import io
import pathlib
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.signal import savgol_filter


def read(path):
    p = pathlib.Path(path)
    if p.is_dir():
        p = next((p / "trials").glob("*.csv"))
    text = p.read_text()
    # Empty cells (a force held between commands) become nan for loadtxt.
    text = text.replace(",,", ",nan,").replace(",\n", ",nan\n")
    return np.loadtxt(io.StringIO(text), delimiter=",", comments="#", skiprows=2)


def main(path):
    data = read(path)
    t, force, pos = data[:, 0], data[:, 1], data[:, 2]
    # The force is held between commands: carry the last value forward.
    idx = np.where(np.isnan(force), 0, np.arange(len(force)))
    force = force[np.maximum.accumulate(idx)]
    ok = ~np.isnan(pos)
    t, force, pos = t[ok], force[ok], pos[ok]
    dt = np.median(np.diff(t))
    v = savgol_filter(pos, 101, 3, deriv=1, delta=dt)  # 1 s window, cubic
    # Integral LS over 1 s intervals: m·Δv = −k∫v − kq∫v|v| + ∫φ + bias·Δt (trapezoids).
    step = int(round(1.0 / dt))
    edges = np.arange(0, len(t) - 1, step)

    def integral(y):
        c = np.concatenate([[0.0], np.cumsum(0.5 * (y[1:] + y[:-1]) * np.diff(t))])
        return c[edges[1:]] - c[edges[:-1]]

    dv = v[edges[1:]] - v[edges[:-1]]
    A = np.column_stack([dv, integral(v), integral(v * np.abs(v)), -np.diff(t[edges])])
    b = integral(force)
    theta, *_ = np.linalg.lstsq(A, b, rcond=None)
    r = b - A @ theta
    cov = np.linalg.inv(A.T @ A) * (r @ r) / (len(b) - A.shape[1])
    m, k, kq, bias = theta
    sig = np.sqrt(np.diag(cov))

    # Free-run score: the fitted model on the logged (held) force, velocity MAE.
    def rhs(tt, x):
        f = force[min(np.searchsorted(t, tt, side="right") - 1, len(t) - 1)]
        return [(-k * x[0] - kq * x[0] * abs(x[0]) + f + bias) / m]

    sim = solve_ivp(rhs, (t[0], t[-1]), [v[0]], t_eval=t, max_step=0.5, rtol=1e-6)
    mae = np.mean(np.abs(sim.y[0] - v)) if sim.success else float("nan")
    print(f"m {m:.4g} ± {sig[0]:.2g} kg, k {k:.4g} ± {sig[1]:.2g} N·s/m, "
          f"kq {kq:.4g} ± {sig[2]:.2g} N·s²/m², bias {bias:.4g} ± {sig[3]:.2g} N; "
          f"free-run velocity MAE {mae:.4g} m/s")


if __name__ == "__main__":
    if len(sys.argv) != 2:
        sys.exit("usage: plain_identify.py CAMPAIGN_DIR_OR_CSV")
    main(sys.argv[1])
