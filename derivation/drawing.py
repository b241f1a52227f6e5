"""How each model draws itself: body points, segments, contact point, outlines.

A :class:`Drawing` is data, like a :class:`~derivation.engine.ModelSpec`:
named points of the body in the world frame (``(x, y, z)``, ``z`` up, the
table is ``z = 0``) as SymPy expressions of the pose-extended state (closed
state, then the pose) and the parameters; segments between named points;
which point is the contact with the table; which points are point masses;
which state entries are tilt angles that a picture may magnify; and optional
outline curves, each a closed curve in the world frame parameterized by
``u`` in ``[0, 2 pi)``.

The emitter (:func:`module_source`, hooked into ``derivation/emit.py``)
writes into every generated module that has a pose

- ``DRAWING``: a plain dict (``points``, ``segments``, ``contact``,
  ``masses``, ``magnify``, ``outlines``, ``description``); ``None`` when the
  model has no drawing;
- ``body_points(s, p)``: compiled, returns an array of shape
  ``(len(DRAWING["points"]), 3)``;
- ``body_outlines(s, p, u)``: compiled, ``u`` a 1-D array of curve
  parameters, returns shape ``(len(DRAWING["outlines"]), len(u), 3)``.

The runtime (``knifeedge.animation``) reads only these.  A model gets its
drawing from ``spec.drawing`` when its :class:`ModelSpec` has one, else from
:data:`DRAWINGS` by model name (:func:`register`).  Another emitter writes
the same three names with :func:`block_source`.

Geometry of the knife edges (paper Figs. ``figg1`` and ``sketch_2modes``):
the bar of half-length ``L`` along the body's ``x`` axis, its middle point
``O`` at ``(x, y)``; two masses ``M/2`` hang at ``ell`` below its ends.  The
body is placed rigidly: orientation ``Rz(phi) Rtilt`` and the height that
puts the contact point on the table.  The tilts are exact rotations whose
first order is the paper's (masses displaced by ``ell theta v_phi``, resp.
``ell (theta1 v_phi - theta2 u_phi)``: the cross terms of the Lagrangians).
"""
from __future__ import annotations

import inspect
from dataclasses import dataclass, field
from pathlib import Path

import sympy as sp

from . import models, sleigh
from .codegen import cse_block, unpack
from .names import Own

#: curve parameter of outlines, ``u`` in ``[0, 2 pi)``
u = Own("u", real=True)  # the emitter's own: written ``u`` in the generated loop


@dataclass(frozen=True)
class Drawing:
    """A body drawn as points, segments and outline curves (world frame).

    Attributes
    ----------
    points : dict name -> (x, y, z) expressions in the pose-extended state and
        the parameters.  Insertion order is the row order of ``body_points``.
    segments : pairs of point names joined by a line (the rigid frame); the
        first is drawn thicker (the body's main member).
    contact : name of the point that touches the table (must be in ``points``).
    masses : names of points drawn as point masses.
    magnify : names of state entries (tilt angles) a picture may multiply by a
        factor to make small rocking visible; positions are never scaled.
    outlines : dict name -> (x, y, z) expressions of ``u`` (closed curves).
    description : one line saying what is drawn.
    gauge : name of the state the picture shows as the spin rate (its gauge);
        ``""``: the model's spin (its first reversal event).
    """

    points: dict
    segments: tuple
    contact: str
    masses: tuple = ()
    magnify: tuple = ()
    outlines: dict = field(default_factory=dict)
    description: str = ""
    gauge: str = ""

    def __post_init__(self):
        for attr in ("points", "outlines"):
            object.__setattr__(self, attr, {k: tuple(sp.sympify(c) for c in v) for k, v in getattr(self, attr).items()})
        names = set(self.points)
        bad = [s for seg in self.segments for s in seg if s not in names]
        bad += [s for s in (self.contact, *self.masses) if s not in names]
        if bad:
            raise ValueError(f"drawing refers to undefined point(s) {sorted(set(bad))}; points are {sorted(names)}")


def _rz(a):
    return sp.Matrix([[sp.cos(a), -sp.sin(a), 0], [sp.sin(a), sp.cos(a), 0], [0, 0, 1]])


def _rx(a):
    return sp.Matrix([[1, 0, 0], [0, sp.cos(a), -sp.sin(a)], [0, sp.sin(a), sp.cos(a)]])


def _ry(a):
    return sp.Matrix([[sp.cos(a), 0, sp.sin(a)], [0, 1, 0], [-sp.sin(a), 0, sp.cos(a)]])


def _place(rotation, body_points: dict, contact_body, origin_xy) -> dict:
    """World coordinates of body-frame points: rotate, put ``origin_xy`` over the origin and the contact on z = 0."""
    height = -(rotation * contact_body)[2]
    origin = sp.Matrix([origin_xy[0], origin_xy[1], height])
    return {k: tuple(origin + rotation * sp.Matrix(v)) for k, v in body_points.items()}


def _knife_edge_frame(L, ell) -> dict:
    return {"O": (0, 0, 0), "end_minus": (-L, 0, 0), "end_plus": (L, 0, 0),
            "mass_minus": (-L, 0, -ell), "mass_plus": (L, 0, -ell)}


_KNIFE_SEGMENTS = (("end_minus", "end_plus"), ("end_minus", "mass_minus"), ("end_plus", "mass_plus"))


def single_mode() -> Drawing:
    """Fig. ``figg1``: the bar on the table rolls by ``theta`` about its own axis; contact ``x + D theta u_phi``."""
    m = models
    rot = _rz(m.phi) * _rx(m.theta)
    body = _knife_edge_frame(m.L, m.ell)
    body["C"] = (m.D * m.theta, 0, 0)
    return Drawing(
        points=_place(rot, body, sp.Matrix(body["C"]), (m.x, m.y)),
        segments=_KNIFE_SEGMENTS, contact="C", masses=("mass_minus", "mass_plus"), magnify=("theta",),
        description=("bar of length 2L on the table (middle point O), masses M/2 hanging ell below its ends, "
                     "contact point C = O + D theta u_phi on the bar (vinculo1, vinculo2)"),
    )


def two_mode() -> Drawing:
    """Fig. ``sketch_2modes``: tilts ``theta1`` (about the bar), ``theta2`` (across it); contact on a circle.

    The contact circle of radius ``D`` stands on the table below the bar's
    middle point ``O`` (its lowest point when untilted), in the vertical plane
    at the chiral angle ``alpha`` from the bar.  The contact is the circle's
    lowest point; to first order it is ``O + D theta_alpha u_alpha``
    (Const22, Const23).
    """
    m = models
    rot = _rz(m.phi) * _rx(m.theta1) * _ry(m.theta2)
    tilt = _rx(m.theta1) * _ry(m.theta2)
    a = sp.Matrix([sp.cos(m.alpha), sp.sin(m.alpha), 0])
    ez = sp.Matrix([0, 0, 1])
    centre = m.D * ez
    # lowest point of the circle centre + D (sin w a - cos w ez): minimise z(w) = ... + D (A sin w - B cos w)
    A, B = (tilt * a)[2], (tilt * ez)[2]
    n = sp.sqrt(A**2 + B**2)
    contact = centre + m.D * (-A / n * a - B / n * ez)
    body = _knife_edge_frame(m.L, m.ell)
    body["C"] = tuple(contact)
    body["circle_centre"] = tuple(centre)
    circle = centre + m.D * (sp.sin(u) * a - sp.cos(u) * ez)
    placed = _place(rot, {**body, "_circle": tuple(circle)}, contact, (m.x, m.y))
    outline = placed.pop("_circle")
    return Drawing(
        points=placed, segments=_KNIFE_SEGMENTS + (("O", "circle_centre"),), contact="C",
        masses=("mass_minus", "mass_plus"), magnify=("theta1", "theta2"), outlines={"contact_circle": outline},
        description=("bar of length 2L (middle point O), masses M/2 hanging ell below its ends, the contact circle "
                     "of radius D at the chiral angle alpha, contact point C its lowest point"),
    )


def chaplygin_sleigh() -> Drawing:
    """The sleigh: a flat disc of radius ``sqrt(2) k`` (radius of gyration ``k``) centred ``a`` ahead of the blade."""
    s = sleigh
    rot = _rz(s.phi)
    h = s.k / 3
    r = sp.sqrt(2) * s.k
    body = {"C": (0, 0, 0), "blade_back": (-s.k / 2, 0, 0), "blade_front": (s.k / 2, 0, 0),
            "blade_top": (0, 0, h), "G": (s.a, 0, h), "nose": (s.a + r, 0, h)}
    disc = (s.a + r * sp.cos(u), r * sp.sin(u), h)
    placed = _place(rot, {**body, "_disc": disc}, sp.Matrix([0, 0, 0]), (s.x, s.y))
    outline = placed.pop("_disc")
    return Drawing(
        points=placed,
        segments=(("blade_back", "blade_front"), ("blade_top", "C"), ("blade_top", "G"), ("G", "nose")),
        contact="C", masses=("G",), outlines={"body": outline},
        description=("flat disc (radius sqrt(2) k, so its radius of gyration is k) with its centre of mass G a "
                     "ahead of the knife edge at the contact C; the knife edge along the axis"),
    )


def rigid_placement(body) -> tuple:
    """``(place, contact)`` for a :class:`~derivation.rigid.RigidBody` at its pose-extended state.

    The rigid modules' state holds the upward vertical ``n`` in body axes and
    the pose ``(psi, x, y)``: heading of the horizontal projection ``X`` of
    the body axis ``e = body.heading_axis`` and the centre of mass.  With
    ``n`` normalized (so that a picture may magnify its horizontal
    components) and ``Y = n x X``, a body vector ``b`` (from the centre of
    mass, body axes) points along ``Rz(psi) (X.b, Y.b, n.b)`` in the world;
    the centre of mass is at height ``-r(n).n`` above the table, ``r(n)`` the
    shape's lowest point (derivation/rigid.py).  ``place(b)`` returns the world
    position of the body point ``b``; ``contact`` is the body vector ``r(n)``.
    """
    from . import rigid

    n = rigid.N_VEC / sp.sqrt(rigid.N_VEC.dot(rigid.N_VEC))
    e = sp.Matrix(body.heading_axis)
    en = e.dot(n)
    X = (e - en * n) / sp.sqrt(e.dot(e) - en**2)
    Y = n.cross(X)
    rot = _rz(rigid.psi) * sp.Matrix.vstack(X.T, Y.T, n.T)
    r = body.shape.lowest_point(n)
    centre = sp.Matrix([rigid.x, rigid.y, -r.dot(n)])

    def place(b) -> tuple:
        return tuple(centre + rot * sp.Matrix(b))

    return place, r


def _sections(a, b, c, centre) -> dict:
    """The three principal sections of an ellipsoid (body frame), as closed curves in ``u``."""
    cx, cy, cz = centre
    cu, su = sp.cos(u), sp.sin(u)
    return {"section_xy": (cx + a * cu, cy + b * su, cz), "section_xz": (cx + a * cu, cy, cz + c * su),
            "section_yz": (cx, cy + b * cu, cz + c * su)}


def _principal_directions(inertia) -> tuple:
    """Unit vectors (body axes) of the principal axes of ``inertia`` whose ``xz`` and ``yz`` entries vanish.

    The horizontal block ``[[I_xx, I_xy], [I_xy, I_yy]]`` has the eigenvector
    of its smaller moment at the angle ``delta = atan2(-2 I_xy, I_yy - I_xx) / 2``
    from the body ``x`` axis (first), that of the larger at ``delta + pi/2``;
    the body ``z`` axis is the third.
    """
    delta = sp.atan2(-2 * inertia[0, 1], inertia[1, 1] - inertia[0, 0]) / 2
    return ((sp.cos(delta), sp.sin(delta), 0), (-sp.sin(delta), sp.cos(delta), 0), (0, 0, 1))


def celt() -> Drawing:
    """The rattleback: its ellipsoid's principal sections, its principal axes of inertia, the contact point.

    Body frame (derivation/celt.py): origin at the centre of mass ``G``, the
    ellipsoid of semi-axes ``a, b, c`` centred ``h`` above it.  The principal
    axes of inertia are drawn through ``G`` (the horizontal ones as long as
    the radius of the ellipsoid's horizontal section along them, the third
    from the ellipsoid's bottom to its top): their turn from the ellipsoid's
    axes, ``delta`` (``tan 2 delta = 2 I_xy / (I_xx - I_yy)``), is the
    chirality.  Exact when ``I_xz = I_yz = 0`` (both
    presets); otherwise the drawn horizontal axes are those of the inertia's
    horizontal block.
    """
    from . import celt as c

    body = c.celt()
    place, r = rigid_placement(body)
    inertia = sp.Matrix(body.inertia)
    d1, d2, d3 = _principal_directions(inertia)
    # each horizontal axis as long as the radius of the ellipsoid's horizontal section along it
    k1 = 1 / sp.sqrt((d1[0] / c.a) ** 2 + (d1[1] / c.b) ** 2)
    k2 = 1 / sp.sqrt((d2[0] / c.a) ** 2 + (d2[1] / c.b) ** 2)
    body_pts = {"G": (0, 0, 0), "C": tuple(r), "E": (0, 0, c.h)}
    for name, d, k in (("axis1", d1, k1), ("axis2", d2, k2)):
        body_pts[f"{name}_minus"] = tuple(-k * v for v in d)
        body_pts[f"{name}_plus"] = tuple(k * v for v in d)
    body_pts["axis3_minus"] = (0, 0, -c.c + c.h)
    body_pts["axis3_plus"] = (0, 0, c.c + c.h)
    sections = _sections(c.a, c.b, c.c, (0, 0, c.h))
    return Drawing(
        points={k: place(v) for k, v in body_pts.items()},
        segments=(("axis1_minus", "axis1_plus"), ("axis2_minus", "axis2_plus"), ("axis3_minus", "axis3_plus")),
        contact="C", masses=("G",), magnify=("n_x", "n_y"),
        outlines={k: place(v) for k, v in sections.items()},
        description=("rattleback: the principal sections of its ellipsoid (semi-axes a, b, c, centre E a height h "
                     "above the centre of mass G), its principal axes of inertia through G (turned by the chirality "
                     "delta from the ellipsoid's axes), the contact point C; tilts magnified by scaling n_x, n_y"),
    )


def two_mode_rigid() -> Drawing:
    """The knife edge of section III as the rigid body (derivation/rigid_knife_edge.py, Fig. ``sketch_2modes``).

    Body frame: origin at the centre of mass ``G`` (midway between the
    masses), ``x`` along the bar, ``z`` up; the bar's ends ``(+-L, 0, ell)``,
    the masses ``(+-L, 0, 0)``, ``O = (0, 0, ell)``; the contact circle of
    radius ``D`` centred ``(0, 0, ell + D)`` in the plane of ``z`` and
    ``a = (cos alpha, sin alpha, 0)``.
    """
    from . import rigid_knife_edge as k

    body = k.knife_edge_body()
    place, r = rigid_placement(body)
    a = sp.Matrix([sp.cos(k.alpha), sp.sin(k.alpha), 0])
    ez = sp.Matrix([0, 0, 1])
    centre = (k.ell + k.D) * ez
    body_pts = {"O": (0, 0, k.ell), "end_minus": (-k.L, 0, k.ell), "end_plus": (k.L, 0, k.ell),
                "mass_minus": (-k.L, 0, 0), "mass_plus": (k.L, 0, 0), "C": tuple(r),
                "circle_centre": tuple(centre)}
    circle = centre + k.D * (sp.sin(u) * a - sp.cos(u) * ez)
    return Drawing(
        points={n: place(v) for n, v in body_pts.items()},
        segments=_KNIFE_SEGMENTS + (("O", "circle_centre"),), contact="C", masses=("mass_minus", "mass_plus"),
        magnify=("n_x", "n_y"), outlines={"contact_circle": place(tuple(circle))},
        description=("inverted-U bar of half-length L (middle point O), masses M/2 hanging ell below its ends, the "
                     "contact circle of radius D at the chiral angle alpha, contact point C its lowest point; "
                     "tilts magnified by scaling n_x, n_y"),
    )


def rigid_body(body) -> Drawing:
    """A plain drawing of any :class:`~derivation.rigid.RigidBody` (used when none is registered).

    The shape's outline (an ellipsoid's principal sections, a circle, a
    sphere's three great circles about its centre), the centre of mass ``G``,
    the contact point and, when the inertia has no ``xz`` and ``yz`` entries,
    its principal axes through ``G``.
    """
    from . import rigid

    place, r = rigid_placement(body)
    shape = body.shape
    size = None
    cu, su = sp.cos(u), sp.sin(u)
    if isinstance(shape, rigid.Ellipsoid):
        outlines = _sections(shape.a, shape.b, shape.c, shape.centre)
        size = sp.Max(shape.a, shape.b, shape.c)
    elif isinstance(shape, rigid.Sphere):
        outlines = _sections(shape.radius, shape.radius, shape.radius, shape.centre)
        size = shape.radius
    elif isinstance(shape, rigid.Circle):
        k = sp.Matrix(shape.axis)
        helper = sp.Matrix([0, 0, 1]) if sp.simplify(k.cross(sp.Matrix([0, 0, 1])).norm()) != 0 else sp.Matrix([1, 0, 0])
        e1 = k.cross(helper)
        e1 = e1 / sp.sqrt(e1.dot(e1))
        e2 = k.cross(e1)
        outlines = {"rim": tuple(sp.Matrix(shape.centre) + shape.radius * (cu * e1 + su * e2))}
        size = shape.radius
    else:
        outlines = {}
    pts = {"G": (0, 0, 0), "C": tuple(r)}
    segments = [("G", "C")]
    inertia = sp.Matrix(body.inertia)
    if size is not None and inertia[0, 2] == 0 and inertia[1, 2] == 0:
        for i, d in enumerate(_principal_directions(inertia), 1):
            pts[f"axis{i}_minus"] = tuple(-size * v for v in d)
            pts[f"axis{i}_plus"] = tuple(size * v for v in d)
            segments.append((f"axis{i}_minus", f"axis{i}_plus"))
    return Drawing(
        points={k: place(v) for k, v in pts.items()}, segments=tuple(segments), contact="C", masses=("G",),
        magnify=("n_x", "n_y"), outlines={k: place(v) for k, v in outlines.items()},
        description=f"{body.name}: the outline of its contact shape, its centre of mass G, the contact C",
    )


#: model name -> its drawing (models whose ModelSpec has no ``drawing`` attribute)
DRAWINGS: dict = {"single_mode": single_mode(), "two_mode": two_mode(), "chaplygin_sleigh": chaplygin_sleigh(),
                  "celt": celt(), "two_mode_rigid": two_mode_rigid()}


#: names given a drawing by :func:`register` (the other entries of DRAWINGS are the package's models')
_REGISTERED: set = set()


def register(name: str, drawing: Drawing) -> None:
    """Declare the drawing of model ``name`` (for models defined outside ``derivation/models.py``)."""
    if not isinstance(drawing, Drawing):
        raise TypeError(f"`drawing` must be a derivation.drawing.Drawing, got {type(drawing).__name__}")
    DRAWINGS[name] = drawing
    _REGISTERED.add(name)


def _from_package(system) -> bool:
    """True if the model of ``system`` is one of the package's (defined under ``derivation/``)."""
    body = getattr(system, "body", None)
    if body is not None:
        return (body.source or "").startswith(("knifeedge.derive.", "derivation."))
    where = getattr(system.spec, "defined_at", "").rsplit(":", 1)[0]
    return bool(where) and Path(where).resolve().parent == Path(__file__).resolve().parent


def drawing_of(spec, package: bool = True) -> Drawing | None:
    """The drawing of a model: ``spec.drawing`` if it has one, else :data:`DRAWINGS` by name (the package's
    models' only when ``package``: a user's model named like a built-in one is not drawn as it), else ``None``."""
    own = getattr(spec, "drawing", None)
    if own is not None or not (package or spec.name in _REGISTERED):
        return own
    return DRAWINGS.get(spec.name)


def source_text() -> str:
    """This module's source (part of the generated modules' input hash)."""
    return inspect.getsource(inspect.getmodule(source_text))


def module_source(system) -> str:
    """The drawing block appended to a generated module with a pose (``""`` without a pose).

    ``DRAWING``, ``body_points(s, p)`` and ``body_outlines(s, p, u)``; see the
    module docstring.  Refuses (``ValueError``) expressions with symbols that
    are not states, pose coordinates, parameters or ``u``.
    """
    spec = system.spec
    if not spec.pose:
        return ""
    drawing = drawing_of(spec, package=_from_package(system))
    if drawing is None and getattr(system, "body", None) is not None:  # a rigid body without its own drawing
        drawing = rigid_body(system.body)
    if drawing is None:
        return "\n\n#: this model has no drawing (derivation/drawing.py)\nDRAWING = None\n"
    return block_source(drawing, tuple(system.state) + tuple(spec.pose), spec.params, spec.name)


def block_source(drawing: Drawing, state, params, name: str = "model") -> str:
    """Source of ``DRAWING``, ``body_points`` and ``body_outlines`` for any emitter.

    Parameters
    ----------
    drawing : the body's :class:`Drawing`.
    state : symbols of the state vector ``s`` the functions receive, in order
        (for the knife edges the closed state followed by the pose).
    params : symbols of the parameter vector ``p``, in order.
    name : the model's name, for error messages.
    """
    allowed = set(state) | set(params)
    state = [str(q) for q in state]
    params = [str(q) for q in params]
    names = list(drawing.points)
    exprs = [c for k in names for c in drawing.points[k]]
    pt_lines, pt_ops = cse_block(exprs, [f"out[{i // 3}, {i % 3}]" for i in range(len(exprs))], allowed)
    onames = list(drawing.outlines)
    oexprs = [c for k in onames for c in drawing.outlines[k]]
    ol_lines, ol_ops = cse_block(oexprs, [f"out[{i // 3}, j, {i % 3}]" for i in range(len(oexprs))],
                                  allowed | {u}, indent="        ")
    missing = [q for q in drawing.magnify if q not in state]
    if missing:
        raise ValueError(f"drawing of {name}: `magnify` names {missing} are not states {state}")
    if drawing.gauge and drawing.gauge not in state:
        raise ValueError(f"drawing of {name}: `gauge` {drawing.gauge!r} is not a state {state}")
    meta = {
        "points": tuple(names), "segments": tuple(tuple(s) for s in drawing.segments), "contact": drawing.contact,
        "masses": tuple(drawing.masses), "magnify": tuple(drawing.magnify), "outlines": tuple(onames),
        "description": drawing.description, **({"gauge": drawing.gauge} if drawing.gauge else {}),
    }
    nl = "\n"
    body = nl.join(pt_lines)
    # the outline expressions are printed with the symbol ``u``: bind it per sample
    outline_loop = (f"    for j in range(uu.shape[0]):\n        u = uu[j]\n{nl.join(ol_lines)}" if onames else "")
    return f'''


#: how to draw the body (derivation/drawing.py): names of the rows of ``body_points``,
#: segments between them, the contact point, the point masses, the tilts a picture may
#: magnify, the outline curves of ``body_outlines``
DRAWING = {meta!r}


@njit(cache=True)
def body_points(s, p):
    """World coordinates (z up, table z = 0) of DRAWING["points"] at the pose-extended state ``s``; shape ({len(names)}, 3) ({pt_ops} operations)."""
    out = np.empty(({len(names)}, 3))
{nl.join(unpack(state, "s"))}
{nl.join(unpack(params, "p"))}
{body}
    return out


@njit(cache=True)
def body_outlines(s, p, uu):
    """World coordinates of the curves DRAWING["outlines"] at the parameters ``uu`` in [0, 2 pi); shape ({len(onames)}, len(uu), 3) ({ol_ops} operations)."""
    out = np.empty(({len(onames)}, uu.shape[0], 3))
{nl.join(unpack(state, "s"))}
{nl.join(unpack(params, "p"))}
{outline_loop}
    return out
'''
