"""The engine behind `intersection.intersect_curves`: Bézier clipping on Python floats, then Newton's method.

Chapter 7 shows the clipping search one pair of pieces and one NumPy step at a
time (`intersection._Search`, recorded by `clip_trace`). A pair of cubics needs
only a handful of clips, and a NumPy call on arrays of four points costs more
than the arithmetic it does, so for polynomial curves this module runs the
same search on Python floats: a piece is two lists of coordinates, a clip a
few dozen multiplications. (Rational curves take the batched NumPy search of
`intersection._batched_search`; `resolve` below serves both.)

The search stops early for a pair of pieces whose tangent directions are
separated (`separated`: they cross at most once): Newton's method on
P(t) - Q(u) = 0 then takes the pair from wherever clipping left it to the
intersection in a few steps, far more cheaply than further clips would.
Where the curves touch, clipping cannot separate them and the pieces around
the contact become tiny and flat to rounding: the first such pair is refined
at once on the tangency system "P(t) - Q(u) is normal to Q'(u) and P'(t) is
parallel to Q'(u)" (`tangency`), whose Jacobian is regular at a contact of
two curves of different curvature, and the stretch of parameters over which
the curves stay within rounding of each other (`contact_extent`) is not
searched again: one contact, one point.

`resolve` turns what a search found into intersections: every box is
refined, as a crossing or else as a tangency; candidates that are the same
intersection (a split point found twice, boxes inside the stretch of a
contact) are merged; a crossing whose rounding could exceed tol/4 gets one
Newton step with the residual in compensated arithmetic (`polish`);
parameters near an end of [0, 1] snap to it when the curves meet there at
least as closely.

Nothing here is public: `intersection.intersect_curves` checks the input and
states what the results promise.
"""

from __future__ import annotations

from math import hypot

EPS = 2.220446049250313e-16
# The constants of the search, shared with the stepper of `intersection` (which says what each does;
# the pad is set there).
SLACK = 4 * EPS
TINY = 1e-6
THIN = 8
OVERLAP_CHECK_AFTER = 500
# This engine splits a pair when a round keeps more than half of both ranges: with the tighter fat lines
# below and the early hand-over to Newton, that costs fewer clips than the notes' 80 % (measured on the
# random cubics of benchmarks/intersection.py).
STALL = 0.5
# With perpendicular=True the perpendicular fat line is clipped against only when the parallel one
# kept more than this fraction (it rarely helps otherwise, and costs a second hull clip).
PERPENDICULAR_AFTER = 0.5
# Newton's method on P(t) = Q(u): at most this many steps; a step counts as converged when it is below
# CONVERGED and at most RATE times the one before (quadratic convergence), or below the rounding level.
CROSSING_STEPS = 16
CONVERGED = 1e-8
RATE = 1e-3
NOISE = 64 * EPS
# The tangency system converges only linearly at a contact of equal curvature: it may take this many steps.
TANGENCY_STEPS = 48
# Boxes left unrefined (neither system settles) closer than this (in both parameters) are one point.
CONTACT = 1e-6
# A tangency found by the search may lie this far from its box (the curves of a triple contact stay within
# rounding of each other over about (1e-12)^(1/3) ~ 1e-4 of the parameters).
REACH = 1e-3
# A contact whose range is wider than this may be an overlap: the overlap check runs at once.
WIDE = 1e-3
# Bisection steps that place the ends of a contact's range (for a contact of higher order, whose middle is
# then the contact).
FINE_STEPS = 30
# The search never resolves boxes finer than this (the fat lines are padded by 1e-12 of the picture).
FLOOR = 1e-12


class GaveUp(RuntimeError):
    """The search used its step budget; carries where it was working."""

    def __init__(self, steps: int, t: float, u: float):
        super().__init__(steps, t, u)
        self.steps, self.t, self.u = steps, t, u


# --- pieces of a curve as lists of floats ----------------------------------------------------------------


def restrict(xs: list, ys: list, a: float, b: float) -> tuple[list, list]:
    """Control points of the part a <= s <= b of a curve (lists xs, ys), over [0, 1]: two de Casteljau passes."""
    n = len(xs) - 1
    if n == 3:
        return _restrict_cubic(xs, ys, a, b)
    xs, ys = list(xs), list(ys)
    if a > 0.0:  # keep [a, 1]: after the in-place passes x[i] is the last point of level n - i
        r = 1.0 - a
        for k in range(n, 0, -1):
            for i in range(k):
                xs[i] = r * xs[i] + a * xs[i + 1]
                ys[i] = r * ys[i] + a * ys[i + 1]
        b = (b - a) / r
    if b < 1.0:  # keep [0, b]: the passes run right to left, x[j] ends as the first point of level j
        r = 1.0 - b
        for k in range(1, n + 1):
            for j in range(n, k - 1, -1):
                xs[j] = r * xs[j - 1] + b * xs[j]
                ys[j] = r * ys[j - 1] + b * ys[j]
    return xs, ys


def _restrict_cubic(xs: list, ys: list, a: float, b: float) -> tuple[list, list]:
    """`restrict` for a cubic, written out (the loops cost more than the arithmetic at this size)."""
    x0, x1, x2, x3 = xs
    y0, y1, y2, y3 = ys
    if a > 0.0:  # the right part of the de Casteljau triangle at a
        r = 1.0 - a
        x01, x12, x23 = r * x0 + a * x1, r * x1 + a * x2, r * x2 + a * x3
        y01, y12, y23 = r * y0 + a * y1, r * y1 + a * y2, r * y2 + a * y3
        x012, x123 = r * x01 + a * x12, r * x12 + a * x23
        y012, y123 = r * y01 + a * y12, r * y12 + a * y23
        x0, x1, x2 = r * x012 + a * x123, x123, x23
        y0, y1, y2 = r * y012 + a * y123, y123, y23
        b = (b - a) / r
    if b < 1.0:  # the left part at b
        r = 1.0 - b
        x01, x12, x23 = r * x0 + b * x1, r * x1 + b * x2, r * x2 + b * x3
        y01, y12, y23 = r * y0 + b * y1, r * y1 + b * y2, r * y2 + b * y3
        x012, x123 = r * x01 + b * x12, r * x12 + b * x23
        y012, y123 = r * y01 + b * y12, r * y12 + b * y23
        x1, x2, x3 = x01, x012, r * x012 + b * x123
        y1, y2, y3 = y01, y012, r * y012 + b * y123
    return [x0, x1, x2, x3], [y0, y1, y2, y3]


# --- one clip --------------------------------------------------------------------------------------------


def kept(d: list, low: float, high: float):
    """The t-extent (lo, hi) of hull{(i/n, d_i)} ∩ {low <= d <= high}, or None (as `intersection._hull_band`).

    If d_0 is in the band the extent starts at 0. If d_0 lies above (below) the band, the hull's vertical
    sections stay above (below) it until they first reach the upper (lower) line, so the extent starts at
    the leftmost crossing of that line by a segment from a control point above (below) to a later one
    that is not; with no such segment every point is outside on that side and nothing is kept. The right
    end is found the same way from d_n.
    """
    n = len(d) - 1
    first, last = d[0], d[n]
    if low <= first <= high:
        left = 0.0
    else:
        s = [v - high for v in d] if first > high else [low - v for v in d]  # > 0: outside, on d_0's side
        left = n + 1.0
        for j in range(1, n + 1):
            sj = s[j]
            if sj <= 0.0:
                for i in range(j):
                    si = s[i]
                    if si > 0.0:
                        x = i + (j - i) * si / (si - sj)
                        if x < left:
                            left = x
        if left > n:
            return None
    if low <= last <= high:
        return left / n, 1.0
    s = [v - high for v in d] if last > high else [low - v for v in d]  # > 0: outside, on d_n's side
    right = -1.0
    for i in range(n):
        si = s[i]
        if si <= 0.0:
            for j in range(i + 1, n + 1):
                sj = s[j]
                if sj > 0.0:
                    x = i + (j - i) * si / (si - sj)
                    if x > right:
                        right = x
    if right < 0.0:
        return None
    return left / n, right / n


def clip(xs: list, ys: list, oxs: list, oys: list, pad: float, perpendicular: bool):
    """The part (lo, hi) of [0, 1] of the piece (xs, ys) that may lie in the fat line(s) of the piece (oxs, oys).

    The fat line is the band around the other piece's chord that holds the other piece, padded by `pad`.
    For a quadratic or cubic the band is narrower than its control points' span: the distance of the
    curve from its chord is d(s) = Σ e_i B_i^n(s) with e_0 = e_n = 0, which is e_1 · 2s(1 - s), at most
    e_1 / 2, for n = 2, and 3s(1 - s)(e_1 (1 - s) + e_2 s), within 3/4 of the larger |e_i| when e_1 e_2 > 0
    and within 4/9 of it otherwise, for n = 3 (Sederberg and Nishita 1990).
    """
    m = len(oxs) - 1
    x0, y0 = oxs[0], oys[0]
    dx, dy = oxs[m] - x0, oys[m] - y0
    length = hypot(dx, dy)
    factor = 1.0
    if length <= pad:  # a closed or tiny piece: the direction to its farthest control point stands in
        far, dx, dy = pad, 1.0, 0.0
        for j in range(1, m + 1):
            ex, ey = oxs[j] - x0, oys[j] - y0
            gap = hypot(ex, ey)
            if gap > far:
                far, dx, dy = gap, ex, ey
        length = hypot(dx, dy)
    ux, uy = dx / length, dy / length
    e = [ux * (y - y0) - uy * (x - x0) for x, y in zip(oxs, oys)]  # signed distances from the chord
    if m == 2 and e[2] == 0.0:
        factor = 0.5
    elif m == 3 and e[3] == 0.0:
        factor = 0.75 if e[1] * e[2] > 0.0 else 4.0 / 9.0
    low = factor * min(min(e), 0.0) - pad
    high = factor * max(max(e), 0.0) + pad
    found = kept([ux * (y - y0) - uy * (x - x0) for x, y in zip(xs, ys)], low, high)
    if found is None or not perpendicular or found[1] - found[0] <= PERPENDICULAR_AFTER:
        return found
    f = [ux * (x - x0) + uy * (y - y0) for x, y in zip(oxs, oys)]
    other = kept([ux * (x - x0) + uy * (y - y0) for x, y in zip(xs, ys)], min(f) - pad, max(f) + pad)
    if other is None:
        return None
    lo, hi = max(found[0], other[0]), min(found[1], other[1])
    return (lo, hi) if lo <= hi else None


def indistinguishable(xs: list, ys: list, limit: float, pad: float) -> bool:
    """A piece smaller than `limit` whose padded fat line is at most THIN pads wide: clips cannot narrow it."""
    if max(xs) - min(xs) > limit or max(ys) - min(ys) > limit:
        return False
    n = len(xs) - 1
    dx, dy = xs[n] - xs[0], ys[n] - ys[0]
    length = hypot(dx, dy)
    if length <= pad:
        return True  # within a pad of a point
    d = [(dy * (xs[0] - xs[i]) + dx * (ys[i] - ys[0])) / length for i in range(n + 1)]
    return max(max(d), 0.0) - min(min(d), 0.0) + 2 * pad <= THIN * pad


def separated(ax: list, ay: list, bx: list, by: list) -> bool:
    """Every tangent direction of piece A strictly on one side of every tangent direction of piece B.

    The differences a_i = A_(i+1) - A_i span the cone of A's tangent directions (the hodograph), and
    likewise b_j for B. If every a_i × b_j has one sign, the pieces cross at most once: a chord
    A(t2) - A(t1) = Σ α_i a_i (α_i >= 0, not all 0) has a cross product of that sign with every b_j, so it
    cannot equal a chord of B, which is ± a combination of the b_j.
    """
    positive = negative = False
    n, m = len(ax) - 1, len(bx) - 1
    for j in range(m):
        bdx, bdy = bx[j + 1] - bx[j], by[j + 1] - by[j]
        for i in range(n):
            c = (ax[i + 1] - ax[i]) * bdy - (ay[i + 1] - ay[i]) * bdx
            if c > 0.0:
                positive = True
            elif c < 0.0:
                negative = True
            else:
                return False
            if positive and negative:
                return False
    return True


# --- the search ------------------------------------------------------------------------------------------


def search(px: list, py: list, qx: list, qy: list, tol: float, max_steps: int, perpendicular: bool,
           scale: float, pad: float, overlap_check=None) -> tuple[list, list, list]:
    """Bézier clipping of two polynomial curves: (boxes, crossings, contacts) found.

    The search of `intersection._Search` on lists of floats. A pair of pieces is clipped, P against Q's
    fat line and then Q against the clipped P's, until both parameter ranges are narrower than tol (a box
    (t_lo, t_hi, u_lo, u_hi, False)), or a round keeps more than STALL of both ranges: then the longer one
    is halved, or, when both pieces are tiny and flat to rounding, the pair is the box of a tangency
    (..., True), refined at once as a contact (`contact_near`) unless it lies in the range of one found
    before; pairs inside such a range are not searched. Pairs whose control points' bounding boxes do
    not meet are dropped at once. When the tangent directions of the two pieces are `separated`,
    Newton's method from where their chords meet finishes the pair: if it lands inside their ranges,
    (t, u, sensitivity) is a crossing (see `crossing`).
    """
    limit = TINY * scale
    margin = NOISE
    boxes, crossings, contacts = [], [], []
    p, q = (px, py, None), (qx, qy, None)
    stack = [(px, py, 0.0, 1.0, qx, qy, 0.0, 1.0)]
    steps = 0
    checked = overlap_check is None
    while stack:
        ax, ay, t0, t1, bx, by, u0, u1 = stack.pop()
        if min(ax) > max(bx) + pad or min(bx) > max(ax) + pad or min(ay) > max(by) + pad or min(by) > max(ay) + pad:
            continue
        if contacts and any(c[2] <= t0 and t1 <= c[3] and c[4] <= u0 and u1 <= c[5] for c in contacts):
            continue  # inside the range of a tangency found before
        while True:
            steps += 1
            if not checked and steps >= OVERLAP_CHECK_AFTER:
                checked = True
                overlap_check()
            if steps > max_steps:
                raise GaveUp(max_steps, t0, u0)
            wt, wu = t1 - t0, u1 - u0
            if wt <= tol and wu <= tol:
                boxes.append((t0, t1, u0, u1, False))
                break
            if wt > tol:  # a converged piece is kept while the other one still needs clipping
                found = clip(ax, ay, bx, by, pad, perpendicular)
                if found is None:
                    break
                a, b = found
                a = a - SLACK if a > SLACK else 0.0
                b = b + SLACK if b < 1.0 - SLACK else 1.0
                if a > 0.0 or b < 1.0:
                    ax, ay = restrict(ax, ay, a, b)
                    t0, t1 = t0 + wt * a, t1 - wt * (1.0 - b)
            if wu > tol or t1 - t0 <= tol:
                found = clip(bx, by, ax, ay, pad, perpendicular)
                if found is None:
                    break
                a, b = found
                a = a - SLACK if a > SLACK else 0.0
                b = b + SLACK if b < 1.0 - SLACK else 1.0
                if a > 0.0 or b < 1.0:
                    bx, by = restrict(bx, by, a, b)
                    u0, u1 = u0 + wu * a, u1 - wu * (1.0 - b)
            if separated(ax, ay, bx, by):
                a, b = chords_meet(ax, ay, bx, by)  # where the chords meet: a start within O(width²)
                found = crossing(px, py, None, qx, qy, None, t0 + (t1 - t0) * a, u0 + (u1 - u0) * b)
                if found is not None:
                    t, u = found[:2]
                    if t0 - margin <= t <= t1 + margin and u0 - margin <= u <= u1 + margin:
                        crossings.append(found)
                        break
            if t1 - t0 > STALL * wt and u1 - u0 > STALL * wu:
                if indistinguishable(ax, ay, limit, pad) and indistinguishable(bx, by, limit, pad):
                    if not _within(contacts, (t0 + t1) / 2, (u0 + u1) / 2):
                        contact = contact_near(p, q, t0, t1, u0, u1, THIN * max(pad, EPS * scale))
                        if contact is not None and not _within(contacts, contact[0], contact[1]):
                            if overlap_check is not None and max(contact[3] - contact[2],
                                                                 contact[5] - contact[4]) > WIDE:
                                overlap_check()
                            contacts.append(contact)
                    boxes.append((t0, t1, u0, u1, True))
                elif t1 - t0 >= u1 - u0:
                    middle = (t0 + t1) / 2
                    stack.append((*restrict(ax, ay, 0.5, 1.0), middle, t1, bx, by, u0, u1))
                    stack.append((*restrict(ax, ay, 0.0, 0.5), t0, middle, bx, by, u0, u1))
                else:
                    middle = (u0 + u1) / 2
                    stack.append((ax, ay, t0, t1, *restrict(bx, by, 0.5, 1.0), middle, u1))
                    stack.append((ax, ay, t0, t1, *restrict(bx, by, 0.0, 0.5), u0, middle))
                break
    return boxes, crossings, contacts


# --- evaluation: point, tangent and curvature vector of a polynomial or rational curve ---------------------


def point_tangent(xs: list, ys: list, ws, s: float) -> tuple[float, float, float, float]:
    """P(s) and P'(s) as (x, y, dx, dy); ws: None (polynomial) or the weights (a rational curve, xs = w x)."""
    n = len(xs) - 1
    r = 1.0 - s
    if n == 3 and ws is None:  # written out for the common cubic
        x0, x1, x2, x3 = xs
        y0, y1, y2, y3 = ys
        x01, x12, x23 = r * x0 + s * x1, r * x1 + s * x2, r * x2 + s * x3
        y01, y12, y23 = r * y0 + s * y1, r * y1 + s * y2, r * y2 + s * y3
        x012, x123 = r * x01 + s * x12, r * x12 + s * x23
        y012, y123 = r * y01 + s * y12, r * y12 + s * y23
        return r * x012 + s * x123, r * y012 + s * y123, 3.0 * (x123 - x012), 3.0 * (y123 - y012)
    x, y = list(xs), list(ys)
    if ws is None:
        for k in range(n, 1, -1):
            for i in range(k):
                x[i] = r * x[i] + s * x[i + 1]
                y[i] = r * y[i] + s * y[i + 1]
        return r * x[0] + s * x[1], r * y[0] + s * y[1], n * (x[1] - x[0]), n * (y[1] - y[0])
    w = list(ws)
    for k in range(n, 1, -1):
        for i in range(k):
            x[i] = r * x[i] + s * x[i + 1]
            y[i] = r * y[i] + s * y[i + 1]
            w[i] = r * w[i] + s * w[i + 1]
    wp = r * w[0] + s * w[1]
    px, py = (r * x[0] + s * x[1]) / wp, (r * y[0] + s * y[1]) / wp
    dw = n * (w[1] - w[0])
    return px, py, (n * (x[1] - x[0]) - dw * px) / wp, (n * (y[1] - y[0]) - dw * py) / wp


def jet(xs: list, ys: list, ws, s: float) -> tuple[float, ...]:
    """P(s), P'(s), P''(s) as (x, y, dx, dy, ddx, ddy), polynomial (ws None) or rational (xs = w x)."""
    n = len(xs) - 1
    if n == 1 and ws is None:
        r = 1.0 - s
        return r * xs[0] + s * xs[1], r * ys[0] + s * ys[1], xs[1] - xs[0], ys[1] - ys[0], 0.0, 0.0
    columns = [xs, ys] if ws is None else [xs, ys, ws]
    values = [_jet_1d(c, s) for c in columns]
    if ws is None:
        (x, dx, ddx), (y, dy, ddy) = values
        return x, y, dx, dy, ddx, ddy
    (X, dX, ddX), (Y, dY, ddY), (W, dW, ddW) = values
    x, y = X / W, Y / W
    dx, dy = (dX - dW * x) / W, (dY - dW * y) / W
    return x, y, dx, dy, (ddX - 2 * dW * dx - ddW * x) / W, (ddY - 2 * dW * dy - ddW * y) / W


def _jet_1d(c: list, s: float) -> tuple[float, float, float]:
    n = len(c) - 1
    if n == 0:
        return c[0], 0.0, 0.0
    r = 1.0 - s
    v = list(c)
    for k in range(n, 2, -1):
        for i in range(k):
            v[i] = r * v[i] + s * v[i + 1]
    if n == 1:
        return r * v[0] + s * v[1], v[1] - v[0], 0.0
    second = n * (n - 1) * ((v[2] - v[1]) - (v[1] - v[0]))
    a, b = r * v[0] + s * v[1], r * v[1] + s * v[2]
    return r * a + s * b, n * (b - a), second


# --- refinement ------------------------------------------------------------------------------------------


def chords_meet(ax: list, ay: list, bx: list, by: list) -> tuple[float, float]:
    """(α, β) with A0 + α (An - A0) = B0 + β (Bm - B0), each clamped to [0, 1]; (0.5, 0.5) for parallel chords."""
    n, m = len(ax) - 1, len(bx) - 1
    rx, ry = ax[n] - ax[0], ay[n] - ay[0]
    sx, sy = bx[m] - bx[0], by[m] - by[0]
    det = rx * sy - ry * sx
    if det == 0.0:
        return 0.5, 0.5
    gx, gy = bx[0] - ax[0], by[0] - ay[0]
    alpha = (gx * sy - gy * sx) / det
    beta = (gx * ry - gy * rx) / det
    return min(max(alpha, 0.0), 1.0), min(max(beta, 0.0), 1.0)


def crossing(px, py, pw, qx, qy, qw, t: float, u: float):
    """Newton's method on P(t) - Q(u) = 0 from (t, u): (t, u, sensitivity), or None if it does not converge.

    Converged means a step below CONVERGED that is at most RATE times the one before (quadratic
    convergence, so the error left is about its square), or a step at the rounding level. sensitivity =
    max(|P'|, |Q'|) / |P' × Q'| at the last step: an error δ in P - Q moves the solution by at most about
    δ times it.
    """
    last = 1.0
    for _ in range(CROSSING_STEPS):
        x1, y1, dx1, dy1 = point_tangent(px, py, pw, t)
        x2, y2, dx2, dy2 = point_tangent(qx, qy, qw, u)
        det = dx1 * dy2 - dy1 * dx2
        if det == 0.0:
            return None
        rx, ry = x2 - x1, y2 - y1
        dt = (rx * dy2 - ry * dx2) / det
        du = (dy1 * rx - dx1 * ry) / det
        t += dt
        u += du
        step = max(abs(dt), abs(du))
        if step <= NOISE or (step <= CONVERGED and step <= RATE * last):
            return t, u, max(hypot(dx1, dy1), hypot(dx2, dy2)) / abs(det)
        if step > 2.0:
            return None  # thrown far out of [0, 1]
        last = step
    return None


def tangency(px, py, pw, qx, qy, qw, t: float, u: float):
    """Newton's method on the tangency system from (t, u): (t, u, gap |P(t) - Q(u)|, converged quadratically).

    g1 = Q'(u) · (P(t) - Q(u)) = 0 (P(t) lies on the normal of Q at u) and g2 = P'(t) × Q'(u) = 0 (parallel
    tangents). At a contact of curves with curvatures κ_P ≠ κ_Q its Jacobian has determinant
    |Q'|^5 λ² (κ_Q - κ_P) (P' = λ Q'), so Newton converges quadratically; at equal curvature it is singular
    and Newton only halves the error per step, to about sqrt(eps).
    """
    last = 1.0
    best = None
    for _ in range(TANGENCY_STEPS):
        x1, y1, dx1, dy1, ddx1, ddy1 = jet(px, py, pw, t)
        x2, y2, dx2, dy2, ddx2, ddy2 = jet(qx, qy, qw, u)
        rx, ry = x1 - x2, y1 - y2
        g1 = dx2 * rx + dy2 * ry
        g2 = dx1 * dy2 - dy1 * dx2
        a11 = dx2 * dx1 + dy2 * dy1
        a12 = ddx2 * rx + ddy2 * ry - (dx2 * dx2 + dy2 * dy2)
        a21 = ddx1 * dy2 - ddy1 * dx2
        a22 = dx1 * ddy2 - dy1 * ddx2
        det = a11 * a22 - a12 * a21
        if det == 0.0:
            break
        dt = (a12 * g2 - a22 * g1) / det
        du = (a21 * g1 - a11 * g2) / det
        t += dt
        u += du
        step = max(abs(dt), abs(du))
        if step > 2.0:
            return None
        best = (t, u)
        if step <= NOISE or (step <= CONVERGED and step <= RATE * last):
            x1, y1 = point_tangent(px, py, pw, t)[:2]
            x2, y2 = point_tangent(qx, qy, qw, u)[:2]
            return t, u, hypot(x1 - x2, y1 - y2), True
        last = step
    if best is None:
        return None
    t, u = best
    x1, y1 = point_tangent(px, py, pw, t)[:2]
    x2, y2 = point_tangent(qx, qy, qw, u)[:2]
    return t, u, hypot(x1 - x2, y1 - y2), False


# --- an accurate residual for the last Newton step (compensated arithmetic) --------------------------------

SPLIT = 134217729.0  # 2^27 + 1: Dekker's splitting of a double into two halves of 26 bits


def accurate_value(c: list, s: float, errors: list | None = None) -> tuple[float, float]:
    """Σ (c_i + errors_i) B_i^n(s) as (value, correction), as accurate as de Casteljau in twice the precision.

    The compensated de Casteljau algorithm (H. Jiang, S. Li, L. Cheng, F. Su, Comput. Math. Appl. 60, 2010):
    every product and sum of the scheme is done with its exact rounding error (Dekker's TwoProduct,
    Knuth's TwoSum; 1 - s = r + ρ exactly), and the errors are carried through the same scheme.
    `errors`: known errors of the coefficients (the rounding of w_i x_i of a rational curve), or None.
    """
    r = 1.0 - s
    z = r - 1.0
    rho = (1.0 - (r - z)) + (-s - z)
    c1 = SPLIT * r
    rh = c1 - (c1 - r)
    rl = r - rh
    c1 = SPLIT * s
    sh = c1 - (c1 - s)
    sl = s - sh
    b, e = list(c), [0.0] * len(c) if errors is None else list(errors)
    for k in range(len(c) - 1, 0, -1):
        for i in range(k):
            a, d = b[i], b[i + 1]
            p1 = r * a
            c1 = SPLIT * a
            ah = c1 - (c1 - a)
            al = a - ah
            e1 = rl * al - (((p1 - rh * ah) - rl * ah) - rh * al)
            p2 = s * d
            c1 = SPLIT * d
            dh = c1 - (c1 - d)
            dl = d - dh
            e2 = sl * dl - (((p2 - sh * dh) - sl * dh) - sh * dl)
            x = p1 + p2
            z = x - p1
            e[i] = (e1 + e2 + ((p1 - (x - z)) + (p2 - z))) + (rho * a + (r * e[i] + s * e[i + 1]))
            b[i] = x
    return b[0], e[0]


def _two_product(a: float, b: float) -> tuple[float, float]:
    p = a * b
    c1 = SPLIT * a
    ah = c1 - (c1 - a)
    al = a - ah
    c1 = SPLIT * b
    bh = c1 - (c1 - b)
    bl = b - bh
    return p, al * bl - (((p - ah * bh) - al * bh) - ah * bl)


def accurate_point(curve, s: float) -> tuple[float, float, float, float]:
    """P(s) as (x, x correction, y, y correction) of a curve (xs, ys, ws) given by its own control points."""
    xs, ys, ws = curve
    if ws is None:
        return (*accurate_value(xs, s), *accurate_value(ys, s))
    w, we = accurate_value(ws, s)
    found = []
    for cs in (xs, ys):
        weighted = [_two_product(c, v) for c, v in zip(cs, ws)]
        v, ve = accurate_value([h for h, _ in weighted], s, [lo for _, lo in weighted])
        x = v / w
        p, pe = _two_product(x, w)  # v + ve - x (w + we) = (v - p) - pe + ve - x we, divided by w
        found += [x, (((v - p) - pe) + (ve - x * we)) / w]
    return tuple(found)


def polish(p, q, t: float, u: float) -> tuple[float, float]:
    """One Newton step on P(t) = Q(u) with the residual in compensated arithmetic.

    p, q: the curves as given, (xs, ys, ws) of their control points and weights (not moved). Newton's
    method in double precision stops where the rounding of the residual, a few eps times the size of the
    control points, divided by sin(angle) |P'| |Q'|, swamps the step; with the residual as accurate as
    twice the precision, one more step brings (t, u) to within a few units in the last place of the
    intersection of the given curves.
    """
    x1, e1, y1, f1 = accurate_point(p, t)
    x2, e2, y2, f2 = accurate_point(q, u)
    rx, ry = (x2 - x1) + (e2 - e1), (y2 - y1) + (f2 - f1)
    dx1, dy1 = point_tangent(*_weighted(p), t)[2:]
    dx2, dy2 = point_tangent(*_weighted(q), u)[2:]
    det = dx1 * dy2 - dy1 * dx2
    if det == 0.0:
        return t, u
    return t + (rx * dy2 - ry * dx2) / det, u + (dy1 * rx - dx1 * ry) / det


def _weighted(curve):
    xs, ys, ws = curve
    if ws is None:
        return curve
    return [x * w for x, w in zip(xs, ws)], [y * w for y, w in zip(ys, ws)], ws


def resolve(boxes, crossings, contacts, p, q, tol: float, scale: float, pad: float, overlap_check=None,
            given=None) -> list:
    """Intersections (t, u), sorted, from what a search found.

    boxes: (t0, t1, u0, u1, tangent); crossings: refined (t, u, sensitivity) (see `crossing`);
    contacts: refined tangencies with the ranges around them where the curves stay within rounding of
    each other, (t, u, t_lo, t_hi, u_lo, u_hi). p, q: (xs, ys, ws) of each curve, moved so that P0 is
    the origin (ws None, or the weights with xs, ys the weighted coordinates); given: the curves as
    given (their own control points and weights), for `polish`; pad: the widening of the fat lines.
    Each box is refined as a crossing or, failing that, as a tangency; a box, crossing or contact
    inside the range of a contact found before is part of it; crossings closer than max(tol, FLOOR)
    are one; a crossing whose rounding could exceed tol/4 is polished.
    """
    if not boxes and not crossings and not contacts:
        return []
    touch = THIN * max(pad, EPS * scale)  # curves closer than this cannot be told apart by the search
    contacts = list(contacts)
    found, loose = list(crossings), []
    for t0, t1, u0, u1, tangent in boxes:
        t, u = (t0 + t1) / 2, (u0 + u1) / 2
        margin = max(t1 - t0, u1 - u0, FLOOR)
        hit = None if tangent else _crossing_in(p, q, t0, t1, u0, u1, margin)
        if hit is not None:
            found.append(hit)
            continue
        if _within(contacts, t, u):
            continue
        contact = contact_near(p, q, t0, t1, u0, u1, touch)
        if contact is not None:
            if not _within(contacts, contact[0], contact[1]):
                if overlap_check is not None and max(contact[3] - contact[2], contact[5] - contact[4]) > WIDE:
                    overlap_check()
                contacts.append(contact)
            continue
        hit = _crossing_in(p, q, t0, t1, u0, u1, margin) if tangent else None
        if hit is not None:
            found.append(hit)
        else:
            loose.append((t, u, t1 - t0, u1 - u0))  # neither system settles: the box, as the search left it
    # A crossing whose rounding could exceed a quarter of tol gets one accurate step. de Casteljau rounds
    # about twice per level and the move by P0 once: the error of P - Q is below (n + m + 2) eps scale.
    rounding = (len(p[0]) + len(q[0])) * EPS * scale
    found = [polish(*given, t, u) if given is not None and rounding * sensitivity > tol / 4 else (t, u)
             for t, u, sensitivity in found]
    reach = max(tol, FLOOR)
    # A contact may snap to an end of [0, 1] anywhere in its range: the curves cannot be told apart there.
    points = [(t, u, max(reach, t - t_lo, t_hi - t), max(reach, u - u_lo, u_hi - u))
              for t, u, t_lo, t_hi, u_lo, u_hi in contacts]
    for group, radius in (([(t, u, 0.0, 0.0) for t, u in found], reach), (loose, max(tol, CONTACT))):
        for t, u, width_t, width_u in sorted(group):
            if _within(contacts, t, u):
                continue
            if not any(abs(t - a) <= radius and abs(u - b) <= radius for a, b, _, _ in points):
                points.append((t, u, max(reach, width_t), max(reach, width_u)))
    rounding = (len(p[0]) + len(q[0])) * EPS * scale
    result = [_snapped(min(max(t, 0.0), 1.0), min(max(u, 0.0), 1.0), p, q, reach_t, reach_u, rounding)
              for t, u, reach_t, reach_u in points]
    result.sort()
    return result


def _within(contacts, t: float, u: float) -> bool:
    return any(c[2] <= t <= c[3] and c[4] <= u <= c[5] for c in contacts)


def _crossing_in(p, q, t0, t1, u0, u1, margin):
    """The crossing that Newton's method finds from the middle of a box, if it lies in the box (± margin)."""
    hit = crossing(*p, *q, (t0 + t1) / 2, (u0 + u1) / 2)
    if hit is not None and t0 - margin <= hit[0] <= t1 + margin and u0 - margin <= hit[1] <= u1 + margin:
        return hit
    return None


def contact_near(p, q, t0, t1, u0, u1, touch: float):
    """The tangency near a box, refined, with its range (t, u, t_lo, t_hi, u_lo, u_hi), or None.

    Newton's method on the tangency system from the middle of the box; the contact counts if the curves
    meet there to within `touch` and it lies within REACH of the box. Its range: how far along P, on
    either side, the curves stay within `touch` of each other (`contact_extent`).
    """
    contact = tangency(*p, *q, (t0 + t1) / 2, (u0 + u1) / 2)
    if contact is None:
        return None
    t, u, gap, converged = contact
    reach = max(t1 - t0, u1 - u0, REACH)
    if gap > touch or not (t0 - reach <= t <= t1 + reach and u0 - reach <= u <= u1 + reach):
        return None
    extent = contact_extent(p, q, t, u, touch, fine=not converged)
    if not converged:  # a contact of higher order: the middle of the range where the curves stay together
        middle = (extent[0] + extent[1]) / 2
        foot = _foot(p, q, middle, u + (middle - t) * _rate(p, q, t, u))
        if foot is not None and foot[1] <= touch:
            t, u = middle, foot[0]
    return (t, u, *extent)


def contact_extent(p, q, t: float, u: float, touch: float, fine: bool = False) -> tuple[float, float, float, float]:
    """The ranges (t_lo, t_hi, u_lo, u_hi) around a contact (t, u) over which P stays within `touch` of Q.

    On each side the offset s = 2^-j along P is found by bisection on j (the distance from P(t ± s) to its
    nearest point on Q grows with s near a contact), then, if `fine`, by bisection on s between 2^-j and
    2^-(j-1); the nearest point's parameter gives the range of u.
    """
    rate = _rate(p, q, t, u)
    t_lo, t_hi, u_lo, u_hi = t, t, u, u
    for side in (-1.0, 1.0):
        near, far = 60, 1  # the distance is within touch at s = 2^-near, assumed not at s = 2^-far
        reached = (t, u)
        while near - far > 1:
            j = (near + far) // 2
            s = side * 2.0**-j
            foot = _foot(p, q, t + s, u + rate * s)
            if foot is not None and foot[1] <= touch:
                near, reached = j, (t + s, foot[0])
            else:
                far = j
        if fine:
            inside, outside = 2.0**-near, 2.0**-far
            for _ in range(FINE_STEPS):
                s = (inside + outside) / 2
                foot = _foot(p, q, t + side * s, u + rate * side * s)
                if foot is not None and foot[1] <= touch:
                    inside, reached = s, (t + side * s, foot[0])
                else:
                    outside = s
        t_lo, t_hi = min(t_lo, reached[0]), max(t_hi, reached[0])
        u_lo, u_hi = min(u_lo, reached[1]), max(u_hi, reached[1])
    return t_lo, t_hi, u_lo, u_hi


def _rate(p, q, t: float, u: float) -> float:
    """du/dt along a contact: |P'| / |Q'| with the sign of P' · Q'."""
    dx1, dy1 = point_tangent(*p, t)[2:]
    dx2, dy2 = point_tangent(*q, u)[2:]
    speed = dx2 * dx2 + dy2 * dy2
    return (dx1 * dx2 + dy1 * dy2) / speed if speed > 0.0 else 0.0


def _foot(p, q, t: float, u: float):
    """(u, distance) of the point of Q nearest to P(t), by Newton's method on (P(t) - Q(u)) · Q'(u) = 0 from u."""
    x1, y1 = point_tangent(*p, t)[:2]
    for _ in range(4):
        x2, y2, dx2, dy2, ddx2, ddy2 = jet(*q, u)
        rx, ry = x1 - x2, y1 - y2
        slope = rx * ddx2 + ry * ddy2 - (dx2 * dx2 + dy2 * dy2)
        if slope == 0.0:
            return None
        u -= (rx * dx2 + ry * dy2) / slope
    x2, y2 = point_tangent(*q, u)[:2]
    return u, hypot(x1 - x2, y1 - y2)


def _snapped(t: float, u: float, p, q, reach_t: float, reach_u: float, rounding: float) -> tuple[float, float]:
    """Move t (u) to an end of [0, 1] within reach_t (reach_u) if the curves meet there as closely.

    For an end of one parameter the other one is moved to the nearest point first (Newton's method on the
    distance); the end is taken if the curves are then at most as far apart as at (t, u), or within the
    rounding of their evaluation. Both ends are preferred to one, one to none.
    """
    ends_t = [e for e in (0.0, 1.0) if abs(t - e) <= reach_t and t != e]
    ends_u = [e for e in (0.0, 1.0) if abs(u - e) <= reach_u and u != e]
    if not ends_t and not ends_u:
        return t, u
    limit = max(_gap(p, q, t, u), rounding)
    candidates = [(a, b) for a in ends_t for b in ends_u]
    candidates += [(e, _nearest(q, u, point_tangent(*p, e)[:2])) for e in ends_t]
    candidates += [(_nearest(p, t, point_tangent(*q, e)[:2]), e) for e in ends_u]
    for a, b in candidates:  # in order of preference
        if 0.0 <= a <= 1.0 and 0.0 <= b <= 1.0 and _gap(p, q, a, b) <= limit:
            return a, b
    return t, u


def _gap(p, q, t: float, u: float) -> float:
    x1, y1 = point_tangent(*p, t)[:2]
    x2, y2 = point_tangent(*q, u)[:2]
    return hypot(x1 - x2, y1 - y2)


def _nearest(curve, s: float, point) -> float:
    """The parameter near s of the point of a curve nearest to `point`: Newton's method on (C(s) - X) · C'(s)."""
    for _ in range(3):
        x, y, dx, dy, ddx, ddy = jet(*curve, s)
        rx, ry = x - point[0], y - point[1]
        slope = dx * dx + dy * dy + rx * ddx + ry * ddy
        if slope <= 0.0:
            break
        s -= (rx * dx + ry * dy) / slope
    return min(max(s, 0.0), 1.0)
