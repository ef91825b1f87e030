"""Peer solvers for the graphplan benchmark, plus an independent closed form.

The benchmark compares graphplan's analytic sweep with two planar-linkage
packages from PyPI. This module solves the *same* linkages with each peer and
returns plain numpy arrays, so the benchmark can time them and diff them
against ``reference_*`` (a closed form written here, independent of both
peers and of graphplan).

The linkages: A) the ratchet four-bar, B) a Watt six-bar (A) plus a dyad on
its coupler point E), C) a slider-crank, centric or offset, its guide
horizontal at y = offset and the slider on the +x side of the crank pin
(the dimensions are keyword arguments, so the benchmark passes its
fixtures').  Both peers model all three, C) with accelerations.

Optional dependencies, the ``bench`` extra (nothing else in graphplan needs
them)::

    bench = ["pylinkage>=1.3", "mechanism>=1.1.10", "numba>=0.60"]

* ``pylinkage`` (HugoFara): ``Linkage`` of ``Ground``/``Crank``/``RRRDyad``/
  ``FixedDyad``/``RRPDyad`` components.  ``step()`` / ``step_with_derivatives()``
  run a Python loop over components; ``step_fast()`` /
  ``step_fast_with_kinematics()`` run the whole sweep in numba (used when
  numba is importable, otherwise the same kernels run as plain Python).
  The crank is *stepped*: each step reads the crank's angle back with
  ``atan2`` and adds ``angular_velocity * dt`` (rad/step).  Dyads pick the
  circle intersection nearest the previous position (branch by hysteresis).
  It computes joint positions, velocities and accelerations; it has no link
  angular velocities/accelerations.
* ``mechanism`` (gabemorris12): you write the vector-loop equations
  yourself; ``Mechanism.iterate()`` calls ``scipy.optimize.fsolve`` on them
  once for positions, once for velocities and once for accelerations at every
  input value, seeding each solve with the previous solution.  Crank angles
  are given as an array, so they are exactly ours.  It reports joint
  positions/velocities/accelerations and, per vector, angle, omega, alpha
  (and r_dot, r_ddot for variable-length vectors such as a slider).

Run ``python bench/peers.py`` to time every peer at N = 1e3, 1e4, 1e5
positions and print the largest difference from the closed form.
"""

from __future__ import annotations

import functools
import math
import warnings

import numpy as np

from graphplan.accuracy import best_time

# --------------------------------------------------------------------------
# The linkages (SI units; x right, y up; angles ccw from +x)
# --------------------------------------------------------------------------

O = (0.0, 0.0)          # crank pivot
C = (0.0, 0.55)         # rocker pivot
CRANK = 0.175           # OA
COUPLER = 0.55          # AB
ROCKER = 0.325          # CB
OMEGA = -17.0           # crank rad/s (clockwise)
EPSILON = 0.0           # crank rad/s^2
S3_ALONG = 0.24         # S3 on AB, this far from A
E_LEFT = 0.125          # E = S3 + this much to the left of A->B

# Six-bar dyad defaults.  Checked with reference_sixbar over a full turn:
# |EF| stays in [0.630, 1.008] m, inside [|ED-DF|, ED+DF] = [0.1, 1.1], and the
# transmission angle at D stays within about 69..133 deg, so it assembles
# everywhere and is far from a dead point.
SIX_ED = 0.6
SIX_DF = 0.5
SIX_F = (-0.55, 0.9)
SIX_D_SIDE = +1         # D on the left of directed line E->F

# Slider-crank C) as timed by main(): centric, and offset by SC_OFFSET; S3 on
# the rod SC_S3 from the crank pin.  The benchmark's fixtures pass their own.
SC_CRANK = 0.1
SC_ROD = 0.4
SC_OFFSET = 0.05
SC_S3 = 0.15
SC_OMEGA = 100.0


# --------------------------------------------------------------------------
# Independent closed form (numpy, vectorised over all angles at once)
# --------------------------------------------------------------------------

def _perp(v):
    """v rotated +90 deg (k x v for a planar vector)."""
    return np.stack([-v[..., 1], v[..., 0]], axis=-1)


def _cross(u, v):
    return u[..., 0] * v[..., 1] - u[..., 1] * v[..., 0]


def _dot(u, v):
    return u[..., 0] * v[..., 0] + u[..., 1] * v[..., 1]


def _rrr_position(p1, p2, l1, l2, side):
    """Joint at distance l1 from p1 and l2 from p2, on the `side` (+1 = left)
    of the directed line p1->p2, i.e. sign(cross(p2-p1, J-p1)) == side."""
    u = p2 - p1
    d2 = _dot(u, u)
    d = np.sqrt(d2)
    a = (l1 * l1 - l2 * l2 + d2) / (2.0 * d)
    h2 = l1 * l1 - a * a
    if np.any(h2 < 0.0):
        raise ValueError("linkage does not assemble at some crank angles")
    h = np.sqrt(h2)
    return p1 + (a / d)[:, None] * u + (side * h / d)[:, None] * _perp(u)


def _rrr_rates(b, c, r):
    """Angular rates of the two links of an RRR dyad.

    Loop closure at joint J, links b = J - P1 and c = J - P2:
        w_b k x b - w_c k x c = R
    where for velocities R = v_P2 - v_P1, and for accelerations
    R = a_P2 - a_P1 + w_b^2 b - w_c^2 c.  Dotting with c and with b
    (k x u . u = 0, k x b . c = cross(b, c)) gives the two rates directly.
    """
    det = _cross(b, c)
    return _dot(r, c) / det, _dot(r, b) / det


def _crank_state(angles, radius, omega, alpha, pivot=(0.0, 0.0)):
    angles = np.asarray(angles, dtype=float)
    rel = radius * np.stack([np.cos(angles), np.sin(angles)], axis=-1)
    pos = np.asarray(pivot, dtype=float) + rel
    vel = omega * _perp(rel)
    acc = alpha * _perp(rel) - omega * omega * rel
    return pos, vel, acc


def reference_fourbar(angles, omega=OMEGA, alpha=EPSILON):
    """Closed-form four-bar A): positions, velocities, accelerations.

    Returns arrays (N, 2) for A, B, S3, E (keys A, B, S3, E, vA, ..., aE) and
    (N,) link rates omega3/alpha3 (coupler AB) and omega4/alpha4 (rocker CB).
    """
    A, vA, aA = _crank_state(angles, CRANK, omega, alpha, O)
    Cp = np.broadcast_to(np.asarray(C, dtype=float), A.shape)
    B = _rrr_position(A, Cp, COUPLER, ROCKER, +1)
    b, c = B - A, B - Cp
    w3, w4 = _rrr_rates(b, c, -vA)                 # v_C = 0
    vB = vA + w3[:, None] * _perp(b)
    r_acc = -aA + (w3 ** 2)[:, None] * b - (w4 ** 2)[:, None] * c
    a3, a4 = _rrr_rates(b, c, r_acc)
    aB = aA + a3[:, None] * _perp(b) - (w3 ** 2)[:, None] * b

    # Coupler points are rigid on link 3: offset from A in the link frame.
    ex = b / COUPLER
    out = {"A": A, "B": B, "vA": vA, "vB": vB, "aA": aA, "aB": aB,
               "omega3": w3, "omega4": w4, "alpha3": a3, "alpha4": a4}
    for name, (along, left) in (("S3", (S3_ALONG, 0.0)), ("E", (S3_ALONG, E_LEFT))):
        rel = along * ex + left * _perp(ex)
        out[name] = A + rel
        out["v" + name] = vA + w3[:, None] * _perp(rel)
        out["a" + name] = aA + a3[:, None] * _perp(rel) - (w3 ** 2)[:, None] * rel
    return out


def reference_sixbar(angles, ED=SIX_ED, DF=SIX_DF, F=SIX_F, d_side=SIX_D_SIDE,
                     omega=OMEGA, alpha=EPSILON):
    """Closed-form Watt six-bar B): four-bar A) plus dyad E-D-F.

    Adds D, vD, aD and omega5/alpha5 (link ED), omega6/alpha6 (link FD).
    """
    out = reference_fourbar(angles, omega, alpha)
    E, vE, aE = out["E"], out["vE"], out["aE"]
    Fp = np.broadcast_to(np.asarray(F, dtype=float), E.shape)
    D = _rrr_position(E, Fp, ED, DF, d_side)
    b, c = D - E, D - Fp
    w5, w6 = _rrr_rates(b, c, -vE)
    vD = vE + w5[:, None] * _perp(b)
    a5, a6 = _rrr_rates(b, c, -aE + (w5 ** 2)[:, None] * b - (w6 ** 2)[:, None] * c)
    aD = aE + a5[:, None] * _perp(b) - (w5 ** 2)[:, None] * b
    out.update(D=D, vD=vD, aD=aD, omega5=w5, omega6=w6, alpha5=a5, alpha6=a6)
    return out


def _slider_geometry(crank, rod, offset):
    """Check a slider-crank's dimensions: the crank must turn fully, so the rod
    must reach the guide from every crank-pin position, rod > crank + |offset|."""
    if not (crank > 0.0 and rod > 0.0):
        raise ValueError(f"slider-crank needs crank > 0 and rod > 0, got crank={crank}, rod={rod}")
    if rod <= crank + abs(offset):
        raise ValueError(f"slider-crank with rod={rod} <= crank + |offset| = {crank + abs(offset)} "
                         "does not turn a full revolution")


def reference_slider_crank(angles, *, crank, rod, offset, s3=None, omega=SC_OMEGA, alpha=0.0):
    """Closed-form slider-crank C): crank O-A about O = (0, 0), rod A-B, slider
    B on the horizontal guide y = offset, on the +x side of the crank pin
    (graphplan's assembly = "forward").  S3 (when s3 is given) lies on AB, s3
    from A.

        x_B = r cos(phi) + sqrt(l^2 - (r sin(phi) - e)^2),   y_B = e

    Rates from the loop closure of the rod: v_B = v_A + w3 k x (B - A) and its
    derivative, with the y components of v_B and a_B zero.  Returns (N, 2)
    arrays A, B[, S3] with their v/a, and (N,) omega3/alpha3 of the rod.
    """
    _slider_geometry(crank, rod, offset)
    A, vA, aA = _crank_state(angles, crank, omega, alpha)
    xB = A[:, 0] + np.sqrt(rod ** 2 - (A[:, 1] - offset) ** 2)
    B = np.stack([xB, np.full_like(xB, offset)], axis=-1)
    b = B - A
    # (k x b)_y = b_x: the y rows of the loop give the rod's rates directly.
    w3 = -vA[:, 1] / b[:, 0]
    a3 = -(aA[:, 1] - w3 ** 2 * b[:, 1]) / b[:, 0]
    vB = vA + w3[:, None] * _perp(b)
    aB = aA + a3[:, None] * _perp(b) - (w3 ** 2)[:, None] * b
    vB[:, 1] = 0.0           # exactly, rather than a rounding residue
    aB[:, 1] = 0.0
    out = {"A": A, "B": B, "vA": vA, "vB": vB, "aA": aA, "aB": aB, "omega3": w3, "alpha3": a3}
    if s3 is not None:
        rel = (s3 / rod) * b
        out.update(S3=A + rel, vS3=vA + w3[:, None] * _perp(rel),
                   aS3=aA + a3[:, None] * _perp(rel) - (w3 ** 2)[:, None] * rel)
    return out


# --------------------------------------------------------------------------
# pylinkage
# --------------------------------------------------------------------------

PYLINKAGE_NOTE = (
    "pylinkage: joint positions, velocities, accelerations only; no link "
    "angular velocities/accelerations. Crank is stepped by a constant "
    "increment (uniform angle grids only); branches follow by hysteresis "
    "from the initial position hint."
)


def _uniform_step(angles):
    """pylinkage advances the crank by a constant angle per step, so it can
    only reproduce a uniformly spaced sweep.  Return that step."""
    angles = np.asarray(angles, dtype=float)
    if angles.size < 2:
        raise ValueError("need at least two crank angles")
    steps = np.diff(angles)
    step = (angles[-1] - angles[0]) / (angles.size - 1)
    if not np.allclose(steps, step, rtol=0.0, atol=1e-12 * max(1.0, abs(step))):
        raise ValueError("pylinkage needs uniformly spaced crank angles")
    return step


def _pylinkage_crank(pl, anchor, radius, angles):
    """Crank whose k-th step lands on angles[k].

    Crank.reload() does angle = atan2(current) + angular_velocity*dt and the
    step generators yield *after* reloading, so the first yielded pose is one
    step past initial_angle: start one step before angles[0].  The angles then
    differ from ours only by the rounding of the repeated atan2/add
    (reported as crank_angle_error: ~4e-13 rad at N=1e4, ~6e-12 rad at
    N=1e5, which is all of pylinkage's difference from the reference).
    """
    step = _uniform_step(angles)
    return pl.Crank(anchor=anchor, radius=radius, angular_velocity=step,
                    initial_angle=float(angles[0]) - step, name="crank")


def _pylinkage_run(linkage, crank, names, n, omega, alpha, kinematics, fast):
    """Sweep n steps and pack the named components into (N, 2) arrays."""
    index = {c.name: i for i, c in enumerate(linkage.components)}
    cols = [index[nm] for nm in names]
    out = {}
    if kinematics:
        linkage.set_input_velocity(crank, omega=omega, alpha=alpha)
    if fast:
        if kinematics:
            pos, vel, acc = linkage.step_fast_with_kinematics(iterations=n)
        else:
            pos, vel, acc = linkage.step_fast(iterations=n), None, None
    elif kinematics:
        rows = list(linkage.step_with_derivatives(iterations=n))
        pos = np.array([r[0] for r in rows], dtype=float)
        vel = np.array([r[1] for r in rows], dtype=float)
        acc = np.array([r[2] for r in rows], dtype=float)
    else:
        pos, vel, acc = np.array(list(linkage.step(iterations=n)), dtype=float), None, None
    for nm, j in zip(names, cols):
        out[nm] = np.ascontiguousarray(pos[:, j])
        if kinematics:
            out["v" + nm] = np.ascontiguousarray(vel[:, j])
            out["a" + nm] = np.ascontiguousarray(acc[:, j])
    return out


def _crank_angle_error(A, angles, pivot=(0.0, 0.0)):
    got = np.arctan2(A[:, 1] - pivot[1], A[:, 0] - pivot[0])
    return float(np.max(np.abs(np.angle(np.exp(1j * (got - angles))))))


def _pylinkage_fourbar_parts(pl, angles):
    """Ground, crank, rocker joint B and coupler points S3, E (as FixedDyads
    on A with the angle measured from A->B)."""
    ref0 = reference_fourbar(angles[:1])        # only used as a branch hint
    o = pl.Ground(*O, name="O")
    c = pl.Ground(*C, name="C")
    crank = _pylinkage_crank(pl, o, CRANK, angles)
    # The RRR dyad keeps the intersection nearest its current position, so
    # the initial hint picks the branch (B left of A->C).
    b = pl.RRRDyad(crank.output, c, distance1=COUPLER, distance2=ROCKER,
                   x=float(ref0["B"][0, 0]), y=float(ref0["B"][0, 1]), name="B")
    s3 = pl.FixedDyad(crank.output, b, distance=S3_ALONG, angle=0.0, name="S3")
    e = pl.FixedDyad(crank.output, b, distance=math.hypot(S3_ALONG, E_LEFT),
                     angle=math.atan2(E_LEFT, S3_ALONG), name="E")
    return [o, c, crank, b, s3, e], crank


def pylinkage_fourbar(angles, kinematics=True, fast=True, omega=OMEGA, alpha=EPSILON):
    """Four-bar A) with pylinkage.  fast=True uses the numba sweep
    (step_fast[_with_kinematics]); fast=False the Python step generators."""
    import pylinkage as pl
    angles = np.asarray(angles, dtype=float)
    parts, crank = _pylinkage_fourbar_parts(pl, angles)
    linkage = pl.Linkage(parts, name="fourbar")
    out = _pylinkage_run(linkage, crank, ["crank", "B", "S3", "E"],
                         angles.size, omega, alpha, kinematics, fast)
    _rename(out, "crank", "A")
    out["crank_angle_error"] = _crank_angle_error(out["A"], angles)
    out["note"] = PYLINKAGE_NOTE
    return out


def pylinkage_sixbar(angles, ED=SIX_ED, DF=SIX_DF, F=SIX_F, d_side=SIX_D_SIDE,
                     kinematics=True, fast=True, omega=OMEGA, alpha=EPSILON):
    """Six-bar B) with pylinkage: four-bar A) plus RRRDyad D on (E, F)."""
    import pylinkage as pl
    angles = np.asarray(angles, dtype=float)
    parts, crank = _pylinkage_fourbar_parts(pl, angles)
    e = parts[-1]
    f = pl.Ground(*F, name="F")
    d0 = reference_sixbar(angles[:1], ED, DF, F, d_side)["D"][0]   # branch hint
    d = pl.RRRDyad(e, f, distance1=ED, distance2=DF, x=float(d0[0]), y=float(d0[1]), name="D")
    linkage = pl.Linkage(parts + [f, d], name="sixbar")
    out = _pylinkage_run(linkage, crank, ["crank", "B", "S3", "E", "D"],
                         angles.size, omega, alpha, kinematics, fast)
    _rename(out, "crank", "A")
    out["crank_angle_error"] = _crank_angle_error(out["A"], angles)
    out["note"] = PYLINKAGE_NOTE
    return out


def pylinkage_slider_crank(angles, *, crank, rod, offset, s3=None, kinematics=True, fast=False,
                           omega=SC_OMEGA, alpha=0.0):
    """Slider-crank C) with pylinkage (geometry as reference_slider_crank).

    The slider is an RRPDyad: circle of radius `rod` about the crank pin cut
    with the line through two Ground points (0, offset) and (1, offset), so an
    offset guide is as easy as a centric one.  Its velocity and acceleration
    come from pylinkage's prismatic solvers (implicit differentiation of the
    circle and line constraints); the rod's omega3/alpha3 are not reported.
    S3 is a FixedDyad on (crank pin, B) at angle 0.
    """
    import pylinkage as pl
    angles = np.asarray(angles, dtype=float)
    geometry = {"crank": crank, "rod": rod, "offset": offset, "s3": s3}
    hint = reference_slider_crank(angles[:1], **geometry)          # branch hint only
    o = pl.Ground(0.0, 0.0, name="O")
    g1 = pl.Ground(0.0, float(offset), name="G1")
    g2 = pl.Ground(1.0, float(offset), name="G2")
    crank_ = _pylinkage_crank(pl, o, crank, angles)
    # The RRP dyad keeps the circle-line intersection nearest its previous
    # position; the hint starts it on the +x branch.
    b = pl.RRPDyad(crank_.output, g1, g2, distance=rod,
                   x=float(hint["B"][0, 0]), y=float(hint["B"][0, 1]), name="B")
    parts, names = [o, g1, g2, crank_, b], ["crank", "B"]
    if s3 is not None:
        parts.append(pl.FixedDyad(crank_.output, b, distance=s3, angle=0.0, name="S3"))
        names.append("S3")
    linkage = pl.Linkage(parts, name="slider-crank")
    out = _pylinkage_run(linkage, crank_, names, angles.size, omega, alpha, kinematics, fast)
    _rename(out, "crank", "A")
    out["crank_angle_error"] = _crank_angle_error(out["A"], angles)
    out["note"] = PYLINKAGE_NOTE
    return out


def _rename(out, old, new):
    for prefix in ("", "v", "a"):
        if prefix + old in out:
            out[prefix + new] = out.pop(prefix + old)


# --------------------------------------------------------------------------
# mechanism (gabemorris12)
# --------------------------------------------------------------------------

MECHANISM_NOTE = (
    "mechanism: joint positions/velocities/accelerations and every vector's "
    "angle, omega, alpha (r_dot/r_ddot for sliders), each from an fsolve of "
    "user-written loop equations per input value (default fsolve tolerance: "
    "agreement ~1e-11 m, ~1e-9 relative in acceleration, not machine "
    "precision). Joint velocity/acceleration "
    "components below 1e-10 are rounded to 0 by the package. Coupler point "
    "E needs its own triangle loop (two extra unknowns)."
)


_ROUGH_STEP = math.radians(5)


def _rough(values, step=_ROUGH_STEP):
    """Initial fsolve guess: the branch we want, rounded to 5 degrees so the
    peer still has to converge on its own."""
    return np.round(np.asarray(values, dtype=float) / step) * step


def _mechanism_fourbar_model(mech, six=None):
    """Vectors and loop equations for A) (and B) when six=(ED, DF, F, side)).

    The coupler AB is split into A->S3 and S3->B sharing one unknown angle
    x[0], which puts S3 exactly on AB.  E is fixed to the coupler by the rigid
    triangle A, S3, E (vectors A->E and S3->E with unknown angles x[2], x[3]),
    the package's own way of modelling a ternary link: an angle *offset*
    inside the loop function would also be applied to omega and alpha, which
    the package passes through the same function.
    """
    joints = mech.get_joints("O A S3 B C E D F" if six else "O A S3 B C E")
    o, a_, s3, b_, c_, e_ = joints[:6]
    a = mech.Vector((o, a_), r=CRANK)
    b1 = mech.Vector((a_, s3), r=S3_ALONG)
    b2 = mech.Vector((s3, b_), r=COUPLER - S3_ALONG)
    g = mech.Vector((o, c_), r=math.hypot(*C), theta=math.atan2(C[1], C[0]), style="ground")
    d = mech.Vector((c_, b_), r=ROCKER)
    ae = mech.Vector((a_, e_), r=math.hypot(S3_ALONG, E_LEFT))
    se = mech.Vector((s3, e_), r=E_LEFT)
    vectors = [a, b1, b2, g, d, ae, se]
    named = {"crank": a, "coupler": b1, "rocker": d}
    if six:
        ED, DF, F, _ = six
        d_, f_ = joints[6:]
        gf = mech.Vector((o, f_), r=math.hypot(*F), theta=math.atan2(F[1], F[0]), style="ground")
        ed = mech.Vector((e_, d_), r=ED)
        fd = mech.Vector((f_, d_), r=DF)
        vectors += [gf, ed, fd]
        named.update(link5=ed, link6=fd)

    def loops(x, inp):
        rows = [a(inp) + b1(x[0]) + b2(x[0]) - d(x[1]) - g(),   # O-A-B-C
                b1(x[0]) + se(x[2]) - ae(x[3])]                 # rigid A-S3-E
        if six:
            rows.append(a(inp) + ae(x[3]) + ed(x[4]) - fd(x[5]) - gf())  # O-A-E-D-F
        return np.concatenate(rows)

    return joints, vectors, named, loops


def _mechanism_run(mech, joints, vectors, loops, angles, omega, alpha, guess, kinematics):
    n = angles.size
    kw = {"vectors": vectors, "origin": joints[0], "loops": loops, "pos": angles,
              "guess": (guess, np.zeros_like(guess), np.zeros_like(guess))}
    if kinematics:
        # The velocity and acceleration loops are linear in their unknowns,
        # so a zero guess is as good as any.
        kw.update(vel=np.full(n, float(omega)), acc=np.full(n, float(alpha)))
    m = mech.Mechanism(**kw)
    with warnings.catch_warnings():
        # fsolve warns "not making good progress" where it stalls; the
        # comparison against the reference is what tells us about accuracy.
        warnings.simplefilter("ignore", RuntimeWarning)
        m.iterate()
    return m


def _mechanism_joint_arrays(joints, names, kinematics):
    out = {}
    by_name = {j.name: j for j in joints}
    for nm in names:
        j = by_name[nm]
        out[nm] = np.stack([j.x_positions, j.y_positions], axis=-1)
        if kinematics:
            out["v" + nm] = np.stack([j.x_velocities, j.y_velocities], axis=-1)
            out["a" + nm] = np.stack([j.x_accelerations, j.y_accelerations], axis=-1)
    return out


def _mechanism_fourbar_guess(ref0, six):
    A, B, S3, E = (ref0[k][0] for k in ("A", "B", "S3", "E"))
    th3 = math.atan2(*(B - A)[::-1])
    th4 = math.atan2(*(B - np.asarray(C))[::-1])
    th_se = math.atan2(*(E - S3)[::-1])
    th_ae = math.atan2(*(E - A)[::-1])
    guess = [th3, th4, th_se, th_ae]
    if six:
        D = ref0["D"][0]
        guess += [math.atan2(*(D - E)[::-1]), math.atan2(*(D - np.asarray(six[2]))[::-1])]
    return _rough(guess)


def mechanism_fourbar(angles, kinematics=True, omega=OMEGA, alpha=EPSILON, _six=None):
    """Four-bar A) with the `mechanism` package (fsolve per crank angle)."""
    import mechanism as mech
    angles = np.asarray(angles, dtype=float)
    ref0 = (reference_sixbar(angles[:1], *_six) if _six
            else reference_fourbar(angles[:1]))                 # branch hint only
    joints, vectors, named, loops = _mechanism_fourbar_model(mech, _six)
    m = _mechanism_run(mech, joints, vectors, loops, angles, omega, alpha,
                       _mechanism_fourbar_guess(ref0, _six), kinematics)
    names = ["A", "B", "S3", "E"] + (["D"] if _six else [])
    out = _mechanism_joint_arrays(m.joints, names, kinematics)
    if kinematics:
        links = {"omega3": "coupler", "omega4": "rocker"}
        if _six:
            links.update(omega5="link5", omega6="link6")
        for key, vec in links.items():
            out[key] = np.array(named[vec].vel.omegas)
            out["alpha" + key[5:]] = np.array(named[vec].acc.alphas)
    out["note"] = MECHANISM_NOTE
    return out


def mechanism_sixbar(angles, ED=SIX_ED, DF=SIX_DF, F=SIX_F, d_side=SIX_D_SIDE,
                     kinematics=True, omega=OMEGA, alpha=EPSILON):
    """Six-bar B) with `mechanism`.  The loop equations do not know about
    branches: d_side only chooses the initial guess, and fsolve then follows
    that branch by continuation (each solve starts from the previous one)."""
    return mechanism_fourbar(angles, kinematics, omega, alpha,
                             _six=(ED, DF, tuple(F), d_side))


def mechanism_slider_crank(angles, *, crank, rod, offset, s3=None, kinematics=True,
                           omega=SC_OMEGA, alpha=0.0):
    """Slider-crank C) with `mechanism` (geometry as reference_slider_crank).

    As in the package's crank-slider example, the slider is a vector of fixed
    angle 0 and unknown length; for an offset guide it starts from the ground
    point G = (0, offset), reached from O by a fixed ground vector, so the loop
    is O-A(-S3)-B-G-O.  With S3 the rod is split into A->S3 and S3->B sharing
    one unknown angle, as the four-bar's coupler.  Reports omega3/alpha3 of the
    rod and the slider's r_dot/r_ddot (slider_v, slider_a).
    """
    import mechanism as mech
    _slider_geometry(crank, rod, offset)
    angles = np.asarray(angles, dtype=float)
    names = ["O", "A", "B"] + (["S3"] if s3 is not None else []) + (["G"] if offset else [])
    joints = dict(zip(names, mech.get_joints(" ".join(names))))
    o, a_, b_ = joints["O"], joints["A"], joints["B"]
    a = mech.Vector((o, a_), r=crank)
    if s3 is not None:
        rod_parts = [mech.Vector((a_, joints["S3"]), r=s3), mech.Vector((joints["S3"], b_), r=rod - s3)]
    else:
        rod_parts = [mech.Vector((a_, b_), r=rod)]
    vectors = [a, *rod_parts]
    if offset:
        g = joints["G"]
        to_guide = mech.Vector((o, g), r=abs(offset), theta=math.copysign(math.pi / 2, offset), style="ground")
        slide = mech.Vector((g, b_), theta=0.0, style="ground")
        vectors += [to_guide, slide]
    else:
        to_guide = None
        slide = mech.Vector((o, b_), theta=0.0, style="ground")
        vectors.append(slide)

    def loops(x, inp):
        row = a(inp) + sum(part(x[0]) for part in rod_parts) - slide(x[1])
        return row - to_guide() if to_guide is not None else row

    hint = reference_slider_crank(angles[:1], crank=crank, rod=rod, offset=offset)
    A0, B0 = hint["A"][0], hint["B"][0]
    guess = np.array([_rough(math.atan2(*(B0 - A0)[::-1])), round(B0[0], 2)])
    m = _mechanism_run(mech, list(joints.values()), vectors, loops, angles, omega,
                       alpha, guess, kinematics)
    out = _mechanism_joint_arrays(m.joints, [n for n in names if n in ("A", "B", "S3")], kinematics)
    if kinematics:
        out["omega3"] = np.array(rod_parts[0].vel.omegas)
        out["alpha3"] = np.array(rod_parts[0].acc.alphas)
        out["slider_v"] = np.array(slide.vel.r_dots)
        out["slider_a"] = np.array(slide.acc.r_ddots)
    out["note"] = MECHANISM_NOTE
    return out


# --------------------------------------------------------------------------
# Comparison and timing
# --------------------------------------------------------------------------

def max_differences(peer, ref):
    """Largest |peer - ref| per kind: positions (m), velocities (m/s),
    accelerations (m/s^2), link rates (rad/s, rad/s^2).  NaN if the peer
    does not provide that kind."""
    kinds = {"pos": [], "vel": [], "acc": [], "omega": [], "alpha": []}
    for key, val in peer.items():
        if key not in ref or not isinstance(val, np.ndarray):
            continue
        diff = float(np.max(np.abs(val - ref[key]))) if np.all(np.isfinite(val)) else math.inf
        if key.startswith("omega"):
            kinds["omega"].append(diff)
        elif key.startswith("alpha"):
            kinds["alpha"].append(diff)
        elif key[0] == "v" and key[1:] in ref:
            kinds["vel"].append(diff)
        elif key[0] == "a" and key[1:] in ref:
            kinds["acc"].append(diff)
        else:
            kinds["pos"].append(diff)
    return {k: (max(v) if v else math.nan) for k, v in kinds.items()}


def sweep(n, omega):
    """n crank angles over one revolution, in the direction of rotation."""
    return math.copysign(1.0, omega) * 2.0 * math.pi * np.arange(n) / n


def main():
    sizes = (10 ** 3, 10 ** 4, 10 ** 5)
    # fsolve three times per position costs about a millisecond: mechanism is
    # timed at no more than 10**4 positions and reported per position.
    mechanism_cap = 10 ** 4
    linkages = {
        "fourbar": (OMEGA, reference_fourbar, {
            "pylinkage": pylinkage_fourbar, "mechanism": mechanism_fourbar}),
        "sixbar": (OMEGA, reference_sixbar, {
            "pylinkage": pylinkage_sixbar, "mechanism": mechanism_sixbar}),
    }
    for lname, offset in (("slider", 0.0), ("slider e", SC_OFFSET)):
        geometry = {"crank": SC_CRANK, "rod": SC_ROD, "offset": offset, "s3": SC_S3}
        linkages[lname] = (SC_OMEGA, functools.partial(reference_slider_crank, **geometry), {
            "pylinkage": functools.partial(pylinkage_slider_crank, **geometry),
            "mechanism": functools.partial(mechanism_slider_crank, **geometry)})
    # Warm-up outside the timings: imports (mechanism pulls in matplotlib)
    # and numba compilation or cache loading on the first call.
    for omega, _, peers in linkages.values():
        for kin in (False, True):
            for fast in (False, True):
                peers["pylinkage"](sweep(10, omega), kinematics=kin, fast=fast)
            peers["mechanism"](sweep(10, omega), kinematics=kin)

    print("pos/s = crank positions solved per second (best of repeats, "
          "including building the peer's model).")
    print("d pos/vel/acc/omega/alpha = largest |peer - reference| in m, m/s, "
          "m/s^2, rad/s, rad/s^2; '-' = not provided.")
    print("d crank = largest crank-angle error of a stepped crank (rad); "
          "d pos* = position difference from the reference evaluated at the "
          "peer's own crank angles.\n")
    header = (f"{'linkage':8} {'solver':22} {'what':8} {'N':>7} {'pos/s':>10} "
              f"{'d pos':>8} {'d vel':>8} {'d acc':>8} {'d omega':>8} {'d alpha':>8} "
              f"{'d crank':>8} {'d pos*':>8}")
    print(header)
    print("-" * len(header))
    for lname, (omega, reference, peers) in linkages.items():
        for n in sizes:
            angles = sweep(n, omega)
            t_ref, ref = best_time(lambda reference=reference, angles=angles: reference(angles), 5)
            _row(lname, "reference (numpy)", "pos+v+a", n, t_ref, {}, None, None)
            runs = [
                ("pylinkage step_fast", peers["pylinkage"], {"fast": True}, 3),
                ("pylinkage step", peers["pylinkage"], {"fast": False}, 3),
                ("mechanism fsolve", peers["mechanism"], {}, 2 if n <= 10 ** 3 else 1),
            ]
            for label, fn, kw, repeats in runs:
                if label.startswith("mechanism") and n > mechanism_cap:
                    print(f"{lname:8} {label:22} not run at N={n}: too slow, see its "
                          f"N={mechanism_cap} rows for the per-position speed")
                    continue
                for kin in (False, True):
                    t, res = best_time(lambda fn=fn, angles=angles, kin=kin, kw=kw: fn(angles, kinematics=kin, **kw), repeats)
                    crank_err = res.get("crank_angle_error")
                    own = None
                    if crank_err is not None:
                        # Separate the stepped crank's drift from solver error.
                        own_angles = np.arctan2(res["A"][:, 1], res["A"][:, 0])
                        own = max_differences(res, reference(own_angles))["pos"]
                    _row(lname, label, "pos+v+a" if kin else "pos", n, t,
                         max_differences(res, ref), crank_err, own)
        print()
    print(PYLINKAGE_NOTE)
    print(MECHANISM_NOTE)


def _row(lname, label, what, n, t, diffs, crank_err, own):
    def f(x):
        return "-" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:8.1e}"
    print(f"{lname:8} {label:22} {what:8} {n:>7} {n / t:10.3e} "
          f"{f(diffs.get('pos')):>8} {f(diffs.get('vel')):>8} {f(diffs.get('acc')):>8} "
          f"{f(diffs.get('omega')):>8} {f(diffs.get('alpha')):>8} {f(crank_err):>8} "
          f"{f(own):>8}", flush=True)


if __name__ == "__main__":
    main()
