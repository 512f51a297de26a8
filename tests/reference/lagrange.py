"""Lagrange's equations of a chain from plain rotation matrices: a check on `chain.py`.

It shares nothing with sympy.physics.mechanics: the kinematics are written as 3x3
matrices (the child's axes in the parent are the columns of Rx, Ry, Rz), the kinetic
energy is 1/2 m v.v + 1/2 w.I w with w from R^T dR/dt, and the loads enter through
virtual work. Slow (hessians of the energy), so meant for n <= 2.

    M = d2T/dqd2,   F = Q + dT/dq - dV/dq - sum_k d(dT/dqd)/dq_k qd_k
"""

from __future__ import annotations

from typing import Callable, Tuple

import sympy as sp

from chain import ChainDescription


def _rotation(axis: str, angle) -> sp.Matrix:
    c, s = sp.cos(angle), sp.sin(angle)
    return {
        "x": sp.Matrix([[1, 0, 0], [0, c, -s], [0, s, c]]),
        "y": sp.Matrix([[c, 0, s], [0, 1, 0], [-s, 0, c]]),
        "z": sp.Matrix([[c, -s, 0], [s, c, 0], [0, 0, 1]]),
    }[axis]


def _unskew(m: sp.Matrix) -> sp.Matrix:
    return sp.Matrix([m[2, 1], m[0, 2], m[1, 0]])


def lagrange_equations(desc: ChainDescription) -> Tuple[Callable, Callable]:
    """Returns (M, F) as functions of (q, qd, param_values_in_desc_order, t)."""
    q = sp.symbols(desc.dofs, real=True)
    qd = sp.symbols([d + "_d" for d in desc.dofs], real=True)
    q, qd = list(q), list(qd)
    t = sp.Symbol("t", real=True)
    p = {name: sp.Symbol(name, real=True) for name in desc.params}
    names = dict(p, t=t)
    dof = dict(zip(desc.dofs, q))

    def rate(m: sp.Matrix) -> sp.Matrix:
        return sum((m.diff(qk) * qdk for qk, qdk in zip(q, qd)), sp.zeros(*m.shape))

    def vec(components) -> sp.Matrix:
        return sp.Matrix([sp.parse_expr(c, local_dict=names) for c in components])

    rotation = {"ground": sp.eye(3)}
    origin = {"ground": sp.zeros(3, 1)}
    kinetic, potential = sp.Integer(0), sp.Integer(0)
    for link in desc.links:
        r, o = rotation[link.parent], origin[link.parent]
        if link.parent_offset is not None:
            o = o + r * sp.Matrix([0, 0, -p[link.parent_offset]])
        for axis, dof_name in link.rotations:
            r = r * _rotation(axis, dof[dof_name])
        rotation[link.body], origin[link.body] = r, o
        com = o + r * vec(link.com)
        v = rate(com)
        w_body = _unskew(r.T * rate(r))
        ixx, iyy, izz, ixy, iyz, ixz = (p[name] for name in link.inertia)
        inertia = sp.Matrix([[ixx, ixy, ixz], [ixy, iyy, iyz], [ixz, iyz, izz]])
        m = p[link.mass]
        kinetic += (m * v.dot(v) + w_body.dot(inertia * w_body)) / 2
        potential += m * p[desc.gravity] * com[2]

    # Generalized forces of the loads by virtual power: Q_k = d(power)/d qd_k, as the
    # load vectors do not depend on qd.
    power = sp.Integer(0)
    for force in desc.forces:
        r, o = rotation[force.body], origin[force.body]
        at = o + r * vec(force.point)
        power += (rotation[force.frame] * vec(force.components)).dot(rate(at))
    for torque in desc.torques:
        r = rotation[torque.body]
        w_ground = r * _unskew(r.T * rate(r))
        power += (rotation[torque.frame] * vec(torque.components)).dot(w_ground)
    # Springs are generalized forces by definition (and depend on qd, so they cannot go
    # through the power above).
    n = len(q)
    spring_force = [sp.Integer(0)] * n
    for spring in desc.springs:
        j = desc.dofs.index(spring.dof)
        spring_force[j] = -p[spring.stiffness] * q[j] - p[spring.damping] * qd[j]

    momentum = [kinetic.diff(v) for v in qd]
    mass = sp.Matrix(n, n, lambda i, j: momentum[i].diff(qd[j]))
    forcing = sp.Matrix([
        power.diff(qd[i]) + spring_force[i] + kinetic.diff(q[i]) - potential.diff(q[i])
        - sum(momentum[i].diff(q[k]) * qd[k] for k in range(n))
        for i in range(n)
    ])
    args = [*q, *qd, *p.values(), t]
    mass_fn = sp.lambdify(args, mass, modules="numpy", cse=True)
    forcing_fn = sp.lambdify(args, forcing, modules="numpy", cse=True)

    def evaluate(fn):
        return lambda qv, qdv, params, tv: fn(*qv, *qdv, *params, tv)

    return evaluate(mass_fn), evaluate(forcing_fn)
