"""An n-link 3D pendulum chain, written both as a yamsc model and as a SymPy system.

The chain is the reference problem for yamsc's equations of motion: every link hangs
from the end of the previous one on a universal joint (`rotate x qa_i; rotate y qb_i`),
has an offset centre of mass and a full inertia tensor, and the chain carries gravity,
torsional spring-dampers, a time-varying point force in ground axes and a torque given
in a body frame. One description (`make_chain`) feeds both writers (`to_mbd`,
`to_sympy`), so the two sides can only disagree if yamsc derives something else.

All numbers are parameters with defaults, so any of them can be overridden on both
sides (`yamsc eval --set name=v`, `params={name: v}` here).
"""

from __future__ import annotations

import math
import random
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

# Load components are written once, as text valid in both the .mbd expression
# language and SymPy (only names, numbers, + - * and cos), so the two sides cannot
# drift apart.
Vector3 = Tuple[str, str, str]


@dataclass
class Link:
    body: str  # body name in the model, e.g. "link2"
    parent: str  # "ground" or the previous link's body name
    parent_offset: Optional[str]  # length parameter of the parent link (child hangs at -L z)
    rotations: List[Tuple[str, str]]  # (axis, dof) steps after the offset, in order
    mass: str
    com: Vector3
    inertia: Tuple[str, str, str, str, str, str]  # Ixx, Iyy, Izz, Ixy, Iyz, Ixz parameters
    length: str


@dataclass
class Spring:
    dof: str
    stiffness: str
    damping: str


@dataclass
class PointForce:
    body: str
    point: Vector3  # in body axes, from the body origin
    frame: str  # frame the components are expressed in
    components: Vector3


@dataclass
class Torque:
    body: str
    frame: str
    components: Vector3


@dataclass
class ChainDescription:
    name: str
    n: int
    dofs: List[str]
    params: Dict[str, float]  # name -> default value, in declaration order
    gravity: str  # parameter name of g; gravity is (0, 0, -g) in ground axes
    links: List[Link]
    springs: List[Spring] = field(default_factory=list)
    forces: List[PointForce] = field(default_factory=list)
    torques: List[Torque] = field(default_factory=list)


def _random_rotation(rng: random.Random) -> List[List[float]]:
    """A uniformly random rotation matrix (from a normalised random quaternion)."""
    w, x, y, z = (rng.gauss(0.0, 1.0) for _ in range(4))
    norm = math.sqrt(w * w + x * x + y * y + z * z)
    w, x, y, z = w / norm, x / norm, y / norm, z / norm
    return [
        [1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
        [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
        [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)],
    ]


def _random_inertia(rng: random.Random, mass: float, length: float) -> List[float]:
    """A physically valid full inertia tensor about the COM: a solid ellipsoid's principal
    moments (so the triangle inequalities hold) turned by a random rotation, so every
    off-diagonal entry is non-zero. Returns (Ixx, Iyy, Izz, Ixy, Iyz, Ixz)."""
    a, b, c = (rng.uniform(0.05, 0.25) * length for _ in range(3))
    c = max(c, 0.4 * length)  # slender along the link, like a real pendulum arm
    principal = [mass / 5 * (b * b + c * c), mass / 5 * (a * a + c * c), mass / 5 * (a * a + b * b)]
    r = _random_rotation(rng)
    tensor = [
        [sum(r[i][k] * principal[k] * r[j][k] for k in range(3)) for j in range(3)]
        for i in range(3)
    ]
    return [tensor[0][0], tensor[1][1], tensor[2][2], tensor[0][1], tensor[1][2], tensor[0][2]]


def make_chain(n: int, seed: int = 1, axes: Sequence[str] = ("x", "y")) -> ChainDescription:
    """An n-link chain with seeded random masses, lengths, COMs and inertias.

    `axes` are the joint rotation axes of every link (default a universal joint
    x then y; ("x",) gives a planar compound-pendulum chain with one DOF per link).
    """
    if n < 1:
        raise ValueError("a chain needs at least one link")
    rng = random.Random(seed)
    params: Dict[str, float] = {"g": 9.81}
    links: List[Link] = []
    dofs: List[str] = []
    dof_prefix = {"x": "qa", "y": "qb", "z": "qc"}
    for i in range(1, n + 1):
        length, mass = rng.uniform(0.5, 1.5), rng.uniform(1.0, 5.0)
        com = [rng.uniform(-0.1, 0.1) * length, rng.uniform(-0.1, 0.1) * length,
               -rng.uniform(0.3, 0.7) * length]
        inertia = _random_inertia(rng, mass, length)
        names = {"L": f"L{i}", "m": f"m{i}"}
        params[names["L"]] = length
        params[names["m"]] = mass
        com_names = (f"cx{i}", f"cy{i}", f"cz{i}")
        for name, value in zip(com_names, com):
            params[name] = value
        inertia_names = tuple(f"{entry}{i}" for entry in ("Ixx", "Iyy", "Izz", "Ixy", "Iyz", "Ixz"))
        for name, value in zip(inertia_names, inertia):
            params[name] = value
        rotations = [(axis, f"{dof_prefix[axis]}{i}") for axis in axes]
        dofs.extend(dof for _, dof in rotations)
        links.append(Link(
            body=f"link{i}",
            parent="ground" if i == 1 else f"link{i - 1}",
            parent_offset=None if i == 1 else f"L{i - 1}",
            rotations=rotations,
            mass=names["m"],
            com=com_names,
            inertia=inertia_names,  # type: ignore[arg-type]
            length=names["L"],
        ))

    # Springs on a few DOFs: the first, one in the middle and the last.
    spring_dofs = sorted({dofs[0], dofs[len(dofs) // 2], dofs[-1]}, key=dofs.index)
    springs = []
    for dof in spring_dofs:
        params[f"K_{dof}"] = rng.uniform(5.0, 50.0)
        params[f"D_{dof}"] = rng.uniform(0.1, 2.0)
        springs.append(Spring(dof, f"K_{dof}", f"D_{dof}"))

    last, first = links[-1], links[0]
    params["px"] = rng.uniform(-0.1, 0.1)
    params["py"] = rng.uniform(-0.1, 0.1)
    params["pz"] = -params[last.length]
    for name in ("Fx", "Fy", "Fz", "Tx", "Ty", "Tz"):
        params[name] = rng.uniform(-5.0, 5.0)
    params["Omega_f"] = rng.uniform(0.5, 3.0)
    # The z component varies in time so the comparison also covers `t` in loads.
    force = PointForce(last.body, ("px", "py", "pz"), "ground", ("Fx", "Fy", "Fz*cos(Omega_f*t)"))
    # The torque's components are given in the first link's axes: a body frame that,
    # for n > 1, is not the loaded body's own frame.
    torque = Torque(last.body, first.body, ("Tx", "Ty", "Tz"))
    return ChainDescription(
        name=f"chain{n}", n=n, dofs=dofs, params=params, gravity="g", links=links,
        springs=springs, forces=[force], torques=[torque],
    )


# --------------------------------------------------------------------------- .mbd


def _vec(v: Sequence[str]) -> str:
    return "(" + ", ".join(v) + ")"


def to_mbd(desc: ChainDescription) -> str:
    """The model in the yamsc language; every number is a parameter default written with
    full double precision (repr round-trips)."""
    out = [f'model {desc.name} "{desc.n}-link 3D pendulum chain (SymPy reference)"', ""]
    for name, value in desc.params.items():
        out.append(f"param {name} = {value!r}")
    out += ["", "dof " + ", ".join(desc.dofs), "", f"gravity (0, 0, -{desc.gravity})", ""]
    for link in desc.links:
        out += [
            f"rigid {link.body} {{",
            f"    mass = {link.mass}",
            f"    com = {_vec(link.com)}",
            f"    inertia = {_vec(link.inertia)}",
            "}",
        ]
    out.append("")
    for link in desc.links:
        steps = [] if link.parent_offset is None else [f"at (0, 0, -{link.parent_offset})"]
        steps += [f"rotate {axis} {dof}" for axis, dof in link.rotations]
        out.append(f"joint {link.parent} -> {link.body} {{ " + "; ".join(steps) + " }")
    out.append("")
    for spring in desc.springs:
        out.append(f"spring {spring.dof} stiffness {spring.stiffness} damping {spring.damping}")
    for force in desc.forces:
        out.append(f"force on {force.body} at {_vec(force.point)} in {force.frame} = "
                   f"{_vec(force.components)}")
    for torque in desc.torques:
        out.append(f"torque on {torque.body} in {torque.frame} = {_vec(torque.components)}")
    return "\n".join(out) + "\n"


# --------------------------------------------------------------------------- SymPy


@dataclass
class SympyDerivation:
    """M(q) q'' = F(q, q', params, t) as SymPy expressions in plain symbols."""

    mass_matrix: "object"  # sympy.Matrix, n x n
    forcing: "object"  # sympy.Matrix, n x 1
    q: list  # Symbols for the DOFs, in desc.dofs order
    qd: list  # Symbols for the DOF rates
    params: list  # Symbols for the parameters, in desc.params order
    t: "object"  # the time Symbol


@dataclass
class KaneEquations:
    """M and F as KanesMethod leaves them: functions of the dynamicsymbols q(t), u(t)."""

    mass_matrix: "object"
    forcing: "object"
    q: list
    u: list
    params: Dict[str, "object"]
    t: "object"


def kane_equations(desc: ChainDescription) -> KaneEquations:
    """Kane's equations of the chain with sympy.physics.mechanics, no simplification
    (the PyDy default). Generalized speeds are the coordinate rates (u = q'). This is
    the whole SymPy derivation that bench/derivation.py times."""
    import sympy as sp
    from sympy.physics import mechanics as me

    t = me.dynamicsymbols._t
    q = me.dynamicsymbols(" ".join(desc.dofs), seq=True)
    u = me.dynamicsymbols(" ".join("u_" + d for d in desc.dofs), seq=True)
    qdot = [qi.diff(t) for qi in q]
    dof = dict(zip(desc.dofs, q))
    # Plain symbols, as PyDy models declare them (assumptions slow the derivation down).
    p = {name: sp.Symbol(name) for name in desc.params}
    expr_names = dict(p, t=t)

    def expr(text: str):
        return sp.parse_expr(text, local_dict=expr_names)

    ground = me.ReferenceFrame("N")
    origin = me.Point("O")
    origin.set_vel(ground, 0)
    frames = {"ground": ground}
    origins = {"ground": origin}
    bodies = []
    loads = []
    gravity = -p[desc.gravity] * ground.z
    for link in desc.links:
        frame, point = frames[link.parent], origins[link.parent]
        if link.parent_offset is not None:
            joint_point = point.locatenew(f"J_{link.body}", -p[link.parent_offset] * frame.z)
            joint_point.v2pt_theory(point, ground, frame)
            point = joint_point
        for step, (axis, dof_name) in enumerate(link.rotations):
            # Each step turns the current frame about its own axis (intrinsic rotations).
            frame = frame.orientnew(f"{link.body}_{step}", "Axis",
                                    (dof[dof_name], getattr(frame, axis)))
        frames[link.body], origins[link.body] = frame, point
        com = point.locatenew(f"G_{link.body}",
                              sum((p[c] * getattr(frame, a) for c, a in zip(link.com, "xyz")),
                                  me.Vector(0)))
        com.v2pt_theory(point, ground, frame)
        ixx, iyy, izz, ixy, iyz, ixz = (p[name] for name in link.inertia)
        inertia = me.inertia(frame, ixx, iyy, izz, ixy, iyz, ixz)
        bodies.append(me.RigidBody(link.body, com, frame, p[link.mass], (inertia, com)))
        loads.append((com, p[link.mass] * gravity))

    def in_frame(components: Vector3, frame_name: str):
        frame = frames[frame_name]
        return sum((expr(c) * getattr(frame, a) for c, a in zip(components, "xyz")),
                   me.Vector(0))

    for force in desc.forces:
        body_frame, body_origin = frames[force.body], origins[force.body]
        at = body_origin.locatenew(f"P_{force.body}", in_frame(force.point, force.body))
        at.v2pt_theory(body_origin, ground, body_frame)
        loads.append((at, in_frame(force.components, force.frame)))
    for torque in desc.torques:
        loads.append((frames[torque.body], in_frame(torque.components, torque.frame)))

    kane = me.KanesMethod(ground, q_ind=q, u_ind=u,
                          kd_eqs=[qd_i - u_i for qd_i, u_i in zip(qdot, u)])
    kane.kanes_equations(bodies, loads)
    mass_matrix, forcing = kane.mass_matrix, kane.forcing

    # Springs are defined on the generalized force itself: F_j += -K q_j - D q_j'.
    spring_force = sp.zeros(len(q), 1)
    for spring in desc.springs:
        j = desc.dofs.index(spring.dof)
        spring_force[j] = -p[spring.stiffness] * q[j] - p[spring.damping] * u[j]
    forcing = forcing + spring_force
    return KaneEquations(mass_matrix, forcing, q, u, p, t)


def derive_sympy(desc: ChainDescription) -> SympyDerivation:
    """Kane's equations of the chain in plain symbols (q_i, q_i' as <dof>_d, t)."""
    import sympy as sp

    kane = kane_equations(desc)
    q, u, t = kane.q, kane.u, kane.t
    q_sym = [sp.Symbol(name, real=True) for name in desc.dofs]
    qd_sym = [sp.Symbol(name + "_d", real=True) for name in desc.dofs]
    t_sym = sp.Symbol("t", real=True)
    # xreplace swaps whole subtrees top-down (q_i'(t) before the q_i(t) inside it) and
    # is far faster than subs on these unsimplified expressions.
    plain = {**dict(zip(u, qd_sym)), **{qi.diff(t): v for qi, v in zip(q, qd_sym)},
             **dict(zip(q, q_sym)), t: t_sym}
    return SympyDerivation(kane.mass_matrix.xreplace(plain), kane.forcing.xreplace(plain),
                           q_sym, qd_sym, list(kane.params.values()), t_sym)


@dataclass
class SympyChain:
    """Numerical M and F of a chain, from SymPy's derivation."""

    desc: ChainDescription
    derivation: SympyDerivation
    _mass: Callable
    _forcing: Callable

    def _args(self, q, qd, params, t):
        values = dict(self.desc.params)
        unknown = set(params or {}) - set(values)
        if unknown:
            raise KeyError(f"unknown parameters: {sorted(unknown)}")
        values.update(params or {})
        if len(q) != len(self.desc.dofs) or len(qd) != len(self.desc.dofs):
            raise ValueError(f"expected {len(self.desc.dofs)} values for q and qd")
        return [*q, *qd, *(values[name] for name in self.desc.params), t]

    def mass_matrix(self, q, qd, params: Optional[Dict[str, float]] = None, t: float = 0.0):
        import numpy as np

        return np.array(self._mass(*self._args(q, qd, params, t)), dtype=float)

    def forcing(self, q, qd, params: Optional[Dict[str, float]] = None, t: float = 0.0):
        import numpy as np

        return np.array(self._forcing(*self._args(q, qd, params, t)), dtype=float).reshape(-1)


def to_sympy(desc: ChainDescription) -> SympyChain:
    """Derive the chain with SymPy and lambdify M and F of (q, qd, params, t)."""
    import sympy as sp

    d = derive_sympy(desc)
    from sympy.core.function import AppliedUndef

    time_functions = (AppliedUndef, sp.Derivative)
    leftover = d.mass_matrix.atoms(*time_functions) | d.forcing.atoms(*time_functions)
    if leftover:
        raise RuntimeError(f"time functions left in the equations: {leftover}")
    args = [*d.q, *d.qd, *d.params, d.t]
    mass = sp.lambdify(args, d.mass_matrix, modules="numpy", cse=True)
    forcing = sp.lambdify(args, d.forcing, modules="numpy", cse=True)
    return SympyChain(desc, d, mass, forcing)
