"""Write the high-precision reference of the combined-load rows of ``bearingload accuracy``.

Run ``python benchmarks/make_combined_reference.py`` (needs mpmath, a test dependency) to
regenerate ``bearingload/quality/data/accuracy_combined_reference.csv``. It shares no code with
the package: the model of ``bearingload.models.combined`` (ISO/TS 16281; Harris & Kotzalas,
*Rolling Bearing Analysis*, 5th ed., ch. 8), as its module docstring states it, is written out
here again in mpmath at 40 significant digits:

* groove centres ``A = (f_i + f_o - 1) D_w`` apart at contact; ``e = G_r/2``; free contact angle
  ``alpha_0 = arccos(1 - e/A)`` (0 under preload); tilt radius ``R = d_m/2 + (f_i - 1/2) D_w
  cos(alpha_0)``;
* ball ``j`` at ``phi_j = cage + 2 pi j/z``: ``rho_j = A - e + x cos phi_j + y sin phi_j``,
  ``u_j = a + R (theta cos phi_j + theta_c sin phi_j)``, approach ``delta_j = sqrt(rho_j^2 +
  u_j^2) - A``, contact angle ``alpha_j = atan2(u_j, rho_j)``, load ``Q_j = K(alpha_j)
  delta_j^1.5`` (``delta_j > 0``);
* ``K(alpha)``: both Hertz contacts in series, ``K = (K_i^(-2/3) + K_o^(-2/3))^(-3/2)``, each
  ``(4 sqrt 2/3) E* / (delta*^1.5 sqrt(sum rho))`` with ``E* = E/(2 (1 - nu^2))``,
  ``delta* = (2 K(e)/pi) (pi/(2 kappa^2 E(e)))^(1/3)`` and the ellipticity from Harris's
  ``F(rho) = ((kappa^2 + 1) E(e) - 2 K(e)) / ((kappa^2 - 1) E(e))``, ``e^2 = 1 - 1/kappa^2``,
  for the curvatures of pitch diameter ``d_m / cos(alpha)`` (Harris & Kotzalas ch. 2, 6);
* equilibrium: ``sum Q_j cos(alpha_j) (cos phi_j, sin phi_j) = (F_r, 0)``, ``sum Q_j
  sin(alpha_j) = F_a``, ``R sum Q_j sin(alpha_j) (cos phi_j, sin phi_j) = (M, M_c)``; an imposed
  misalignment fixes ``theta`` and the first moment is then the one needed.

Solved by Newton on the convex potential ``sum K_j/2.5 delta_j^2.5 - F . v`` with the stiffnesses
frozen (Armijo line search, a start that loads the balls), then Newton steps with the frozen-K
Hessian on the full equations until the residual is below 1e-35 of the load; the file keeps 30
digits of the state and of ``Q_max``.
"""

from __future__ import annotations

import os
import sys

import mpmath as mp

DIGITS = 40
GEOMETRY = {"balls": 7, "ball_diameter": 11.5, "pitch_diameter": 43.5, "f_i": 0.52, "f_o": 0.53}
MATERIAL = {"modulus": 208000.0, "poisson": 0.3}
#: (label (no commas: a csv cell), F_r [N], F_a [N], M [N mm], misalignment [°] or None,
#: G_r [mm], cage angle [°])
CASES = (
    ("radial; G_r = 0", 1000.0, 0.0, 0.0, None, 0.0, 0.0),
    ("combined; G_r = 10 um", 1000.0, 500.0, 0.0, None, 0.01, 0.0),
    ("combined; half pitch; G_r = 20 um", 1000.0, 200.0, 0.0, None, 0.02, 180.0 / 7),
    ("axial only; G_r = 10 um", 0.0, 1000.0, 0.0, None, 0.01, 0.0),
    ("moment 2e4 N mm; G_r = 10 um", 1000.0, 300.0, 2.0e4, None, 0.01, 0.0),
    ("combined; preload G_r = -10 um", 1000.0, 500.0, 0.0, None, -0.01, 0.0),
    ("radial; preload G_r = -30 um", 1000.0, 0.0, 0.0, None, -0.03, 0.0),
    ("combined; preload -10 um; cage 10 deg", 1000.0, 500.0, 0.0, None, -0.01, 10.0),
    ("light load; preload G_r = -30 um", 10.0, 5.0, 0.0, None, -0.03, 0.0),
    ("combined; preload G_r = -30 um; moment", 1000.0, 500.0, 1.0e4, None, -0.03, 0.0),
    ("misalignment 0.05 deg; G_r = 10 um", 1000.0, 500.0, 0.0, 0.05, 0.01, 0.0),
    ("misalignment exactly 0; G_r = 10 um", 1000.0, 500.0, 0.0, 0.0, 0.01, 0.0),
)
OUT = os.path.join(
    os.path.dirname(__file__),
    "..",
    "bearingload",
    "quality",
    "data",
    "accuracy_combined_reference.csv",
)
#: The columns in the project's vocabulary (``bearingload.reports.quantities``: ``key [unit]``,
#: the radial load ``load``, angles in °); ``moment_out`` is the moment the equilibrium needs.
HEADER = (
    "case,label,balls,ball_diameter [mm],pitch_diameter [mm],f_i,f_o,modulus [MPa],poisson,"
    "load [N],axial_load [N],moment [N mm],misalignment [°],clearance [mm],"
    "cage_angle [°],x [mm],y [mm],axial [mm],tilt [°],tilt_cross [°],moment_out [N mm],"
    "q_max [N]"
)


def contact_stiffness(rho_x: mp.mpf, rho_y: mp.mpf, e_star: mp.mpf) -> mp.mpf:
    """Hertz point-contact stiffness K, Q = K delta^1.5. [N/mm^1.5]"""
    total = rho_x + rho_y
    f_rho = abs(rho_x - rho_y) / total
    if f_rho == 0:
        d_star = mp.mpf(1)
    else:

        def equation(log_kappa: mp.mpf) -> mp.mpf:
            k2 = mp.exp(2 * log_kappa)
            m = 1 - 1 / k2
            big_k, big_e = mp.ellipk(m), mp.ellipe(m)
            return ((k2 + 1) * big_e - 2 * big_k) / ((k2 - 1) * big_e) - f_rho

        ratio = max(rho_x, rho_y) / min(rho_x, rho_y)
        start = mp.log(ratio) * 2 / (3 * mp.pi) * 1.0339  # Hamrock-Brewe, only a start
        t = mp.findroot(equation, start, tol=mp.mpf(10) ** (-DIGITS + 2))
        k2 = mp.exp(2 * t)
        m = 1 - 1 / k2
        d_star = 2 * mp.ellipk(m) / mp.pi * mp.cbrt(mp.pi / (2 * k2 * mp.ellipe(m)))
    return 4 * mp.sqrt(2) / 3 * e_star / (d_star**1.5 * mp.sqrt(total))


def ball_stiffness(alpha: mp.mpf, g: dict) -> mp.mpf:
    """Both contacts in series at the contact angle alpha (pitch diameter d_m / cos alpha)."""
    dw, fi, fo = g["dw"], g["fi"], g["fo"]
    dm = g["dm"] / mp.cos(alpha)
    e_star = g["E"] / (2 * (1 - g["nu"] ** 2))
    k_i = contact_stiffness(2 * dm / (dw * (dm - dw)), (2 * fi - 1) / (fi * dw), e_star)
    k_o = contact_stiffness(2 * dm / (dw * (dm + dw)), (2 * fo - 1) / (fo * dw), e_star)
    return (k_i ** (-mp.mpf(2) / 3) + k_o ** (-mp.mpf(2) / 3)) ** (-mp.mpf(3) / 2)


def balls(v: list, g: dict) -> list[tuple]:
    """Per ball: (delta, alpha, d delta/dv (5), d^2 delta/dv^2 (5x5)) at v = (x, y, a, th, th_c)."""
    out = []
    for phi in g["phi"]:
        c, s = mp.cos(phi), mp.sin(phi)
        rho = g["A"] - g["e"] + v[0] * c + v[1] * s
        u = v[2] + g["R"] * (v[3] * c + v[4] * s)
        d = mp.sqrt(rho**2 + u**2)
        d_rho, d_u = [c, s, 0, 0, 0], [0, 0, 1, g["R"] * c, g["R"] * s]
        grad = [(rho * d_rho[i] + u * d_u[i]) / d for i in range(5)]
        hess = [
            [(d_rho[i] * d_rho[k] + d_u[i] * d_u[k] - grad[i] * grad[k]) / d for k in range(5)]
            for i in range(5)
        ]
        out.append((d - g["A"], mp.atan2(u, rho), grad, hess))
    return out


def forces(v: list, g: dict, k: list) -> tuple[list, mp.matrix, mp.mpf]:
    """Gradient of the potential (ball forces minus the applied), its Hessian with K frozen,
    and the potential."""
    grad = [-f for f in g["F"]]
    hess = mp.zeros(5, 5)
    pot = -sum(g["F"][i] * v[i] for i in range(5))
    for (delta, _, dd, d2), kj in zip(balls(v, g), k, strict=True):
        if delta <= 0:
            continue
        q = kj * delta**1.5
        pot += kj / mp.mpf(2.5) * delta**2.5
        for i in range(5):
            grad[i] += q * dd[i]
            for m in range(5):
                hess[i, m] += 1.5 * kj * mp.sqrt(delta) * dd[i] * dd[m] + q * d2[i][m]
    return grad, hess, pot


def newton_step(v: list, g: dict, k: list) -> tuple[list, list]:
    """The free unknowns' Newton step of the frozen-K equations, and the gradient."""
    grad, hess, _ = forces(v, g, k)
    free = g["free"]
    h = mp.matrix([[hess[i, m] for m in free] for i in free])
    h += mp.eye(len(free)) * mp.mpf(10) ** (-DIGITS) * max(abs(h[i, i]) for i in range(len(free)))
    step = mp.lu_solve(h, mp.matrix([-grad[i] for i in free]))
    full = [mp.mpf(0)] * 5
    for n, i in enumerate(free):
        full[i] = step[n]
    return full, grad


def minimise(v: list, g: dict, k: list) -> list:
    """Damped Newton on the convex potential with K frozen."""
    for _ in range(200):
        step, grad = newton_step(v, g, k)
        _, _, pot = forces(v, g, k)
        slope = sum(grad[i] * step[i] for i in range(5))
        t = mp.mpf(1)
        while True:
            trial = [v[i] + t * step[i] for i in range(5)]
            if forces(trial, g, k)[2] <= pot + mp.mpf("1e-4") * t * slope or t < 1e-30:
                break
            t /= 2
        v = trial
        if max(abs(step[i]) for i in range(5)) < mp.mpf(10) ** (-DIGITS + 5) * g["scale"]:
            break
    return v


def solve_case(case: tuple) -> dict:
    """The reference state of one case."""
    label, fr, fa, moment, tilt, gr, cage = case
    with mp.workdps(DIGITS):
        g = {
            "dw": mp.mpf(GEOMETRY["ball_diameter"]),
            "dm": mp.mpf(GEOMETRY["pitch_diameter"]),
            "fi": mp.mpf(GEOMETRY["f_i"]),
            "fo": mp.mpf(GEOMETRY["f_o"]),
            "E": mp.mpf(MATERIAL["modulus"]),
            "nu": mp.mpf(MATERIAL["poisson"]),
        }
        z = GEOMETRY["balls"]
        g["A"] = (g["fi"] + g["fo"] - 1) * g["dw"]
        g["e"] = mp.mpf(gr) / 2
        alpha0 = mp.acos(1 - g["e"] / g["A"]) if gr > 0 else mp.mpf(0)
        g["R"] = g["dm"] / 2 + (g["fi"] - mp.mpf(1) / 2) * g["dw"] * mp.cos(alpha0)
        g["phi"] = [mp.radians(mp.mpf(cage)) + 2 * mp.pi * j / z for j in range(z)]
        g["F"] = [mp.mpf(fr), mp.mpf(0), mp.mpf(fa), mp.mpf(moment), mp.mpf(0)]
        g["free"] = [0, 1, 2, 4] if tilt is not None else [0, 1, 2, 3, 4]
        k0 = ball_stiffness(mp.mpf(0), g)
        g["scale"] = (max(abs(mp.mpf(fr)), abs(mp.mpf(fa))) / k0) ** (mp.mpf(2) / 3)
        play = mp.sqrt(max(g["A"] ** 2 - (g["A"] - g["e"]) ** 2, 0))
        sign = 1 if fa >= 0 else -1
        v = [
            max(g["e"], 0) + (g["scale"] if fr > 0 else 0),
            mp.mpf(0),
            sign * (play + g["scale"]) if fa != 0 else mp.mpf(0),
            mp.radians(mp.mpf(tilt)) if tilt is not None else mp.mpf(0),
            mp.mpf(0),
        ]
        k = [k0] * z
        v = minimise(v, g, k)
        for _ in range(60):  # K(alpha_j) at the current angles, Newton with the frozen Hessian
            k = [ball_stiffness(b[1], g) for b in balls(v, g)]
            step, grad = newton_step(v, g, k)
            v = [v[i] + step[i] for i in range(5)]
            load = max(abs(f) for f in g["F"][:3])
            if max(abs(grad[i]) for i in g["free"]) < mp.mpf(10) ** (-DIGITS + 5) * load:
                break
        else:
            raise RuntimeError(f"{label}: no convergence")
        state = balls(v, g)
        k = [ball_stiffness(b[1], g) for b in state]
        q = [kj * b[0] ** 1.5 if b[0] > 0 else mp.mpf(0) for b, kj in zip(state, k, strict=True)]
        needed = g["R"] * sum(
            qj * mp.sin(b[1]) * mp.cos(phi) for qj, b, phi in zip(q, state, g["phi"], strict=True)
        )
        return {
            "x": v[0],
            "y": v[1],
            "axial": v[2],
            "tilt": mp.degrees(v[3]),
            "tilt_cross": mp.degrees(v[4]),
            "moment_out": needed if tilt is not None else mp.mpf(moment),
            "q_max": max(q),
        }


def main() -> None:
    lines = [HEADER]
    for n, case in enumerate(CASES, start=1):
        label, fr, fa, moment, tilt, gr, cage = case
        ref = solve_case(case)
        geo = ",".join(repr(GEOMETRY[k]) for k in GEOMETRY)
        mat = ",".join(repr(MATERIAL[k]) for k in MATERIAL)
        inputs = f"{fr!r},{fa!r},{moment!r},{'' if tilt is None else repr(tilt)},{gr!r},{cage!r}"
        # below 1e-30 (of a mm, a degree or a N mm) a component is rounding noise of a zero
        values = ",".join(
            mp.nstr(ref[k] if abs(ref[k]) > 1e-30 else 0, 30, strip_zeros=False) for k in ref
        )
        lines.append(f"{n},{label},{geo},{mat},{inputs},{values}")
        print(lines[-1], file=sys.stderr)
    with open(OUT, "w", encoding="utf-8", newline="\n") as fh:
        fh.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
