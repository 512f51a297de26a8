"""yamsc models from Python (docs/python.md).

    import yamsc
    m = yamsc.load("models/double_pendulum.mbd", set={"k": 8.0})
    M = m.mass_matrix(q)                     # numpy arrays in and out
    run = m.simulate(10.0, 1e-3, u={"tau": 1.0})

The model is compiled through the same cache as `yamsc sim` (one shared
library per model and content); evaluations call the generated code directly.
Arrays that are contiguous float64 are read in place, others are converted
once. Errors in a model raise yamsc.Error with yamsc's located message.
"""
from typing import NamedTuple, Optional

import math

import numpy as np

from . import _yamsc

__all__ = ["Error", "Model", "Quantity", "ROUTINES", "SIMULATE", "load", "load_library"]

Error = _yamsc.Error


class Quantity(NamedTuple):
    """A DOF, input channel, parameter or output of a model."""
    name: str
    unit: str  # from the doc comment's trailing [unit]; "" when not written
    doc: str
    default: Optional[float] = None  # parameters: the model's default (None: none)
    value: Optional[float] = None    # parameters: the value bound at load()


def _pandas(frame):
    """pandas when a DataFrame is wanted: `frame` True (pandas required) or
    None (if pandas is installed); else None."""
    if not (frame is None or frame):
        return None
    try:
        import pandas
    except ImportError:
        if frame:
            raise
        return None
    return pandas

def _assignments(values, what):
    """{"psi'": 1.2} -> [("psi", 1, 1.2)]: the driver's Assignment (name, primes, value)."""
    if values is None:
        return []
    if not isinstance(values, dict):
        raise TypeError(f"{what} must be a dict of name: value")
    out = []
    for name, value in values.items():
        base = name.rstrip("'")
        out.append((base, len(name) - len(base), float(value)))
    return out


def _sid_spec(sid):
    """sid="body=file.sid,..." or {"body": "file.sid"} -> the --sid text."""
    if sid is None:
        return ""
    if isinstance(sid, dict):
        return ",".join(f"{body}={path}" for body, path in sid.items())
    return str(sid)


class _Outputs(list):
    """The model's outputs: a list of Quantity and, called, their values."""

    def __init__(self, items, model):
        super().__init__(items)
        self._model = model

    def __call__(self, q, qd=None, u=None, t=0.0, p=None):
        return self._model._evaluate_outputs(q, qd, u, t, p)


class Model:
    """A compiled model. Use yamsc.load() or yamsc.load_library()."""

    def __init__(self, handle):
        self._h = handle
        described = {k: handle.described(k) for k in ("dofs", "inputs", "params", "outputs")}
        make = lambda d: Quantity(d.name, d.unit, d.doc)
        self.dofs = [make(d) for d in described["dofs"]]
        self.inputs = [make(d) for d in described["inputs"]]
        defaults, bound = handle.default_params, handle.params
        self.params = [Quantity(d.name, d.unit, d.doc,
                                None if math.isnan(defaults[i]) else float(defaults[i]),
                                float(bound[i]))
                       for i, d in enumerate(described["params"])]
        self.outputs = _Outputs([make(d) for d in described["outputs"]], self)
        self._param_index = {q.name: i for i, q in enumerate(self.params)}
        self._input_index = {q.name: i for i, q in enumerate(self.inputs)}

    # -- information -----------------------------------------------------
    @property
    def name(self):
        """The model's name ("" for a library)."""
        return self._h.name

    @property
    def library_path(self):
        """The shared library the model runs from (the JIT cache's for load())."""
        return self._h.library_path

    @property
    def nq(self):
        return self._h.nq

    @property
    def nu(self):
        return self._h.nu

    @property
    def ny(self):
        return self._h.ny

    @property
    def param_values(self):
        """The bound parameters as an array (load()'s set= applied)."""
        return self._h.params

    def columns(self):
        """The columns of simulate(): time, DOFs, DOF rates, outputs (as `yamsc sim` writes)."""
        return (["time"] + [d.name for d in self.dofs] + [d.name + "'" for d in self.dofs]
                + [o.name for o in self.outputs])

    def __repr__(self):
        return (f"<yamsc.Model {self.name or self.library_path}: {self.nq} DOFs, "
                f"{self.nu} inputs, {len(self.params)} parameters, {self.ny} outputs>")

    # -- arguments -------------------------------------------------------
    def _p(self, p):
        """None, np values, or {name: value} over the bound parameters."""
        if p is None or not isinstance(p, dict):
            return p
        values = np.array(self._h.params)
        for name, value in p.items():
            if name not in self._param_index:
                raise Error(f"unknown parameter '{name}'")
            values[self._param_index[name]] = value
        return values

    def _u(self, u):
        """None, nu values, or {channel: value} (others 0)."""
        if u is None or not isinstance(u, dict):
            return u
        values = np.zeros(self.nu)
        for name, value in u.items():
            if name not in self._input_index:
                raise Error(f"unknown input '{name}'")
            values[self._input_index[name]] = value
        return values

    # -- evaluation ------------------------------------------------------
    def mass_matrix(self, q, p=None, u=None, t=0.0):
        """M(q) (nq x nq); it depends on u and t only with prescribed motion."""
        return self._h.mass_matrix(q, self._u(u), t, self._p(p))

    def forcing(self, q, qd, u=None, t=0.0, p=None):
        """F(q, q', u, t): M q'' = F."""
        return self._h.forcing(q, qd, self._u(u), t, self._p(p))

    def rhs(self, x, u=None, t=0.0, p=None):
        """x' for x = [q, q'] (2 nq values)."""
        return self._h.rhs(x, self._u(u), t, self._p(p))

    def rhs_jacobian(self, x, u=None, t=0.0, p=None):
        """d(x')/dx (2nq x 2nq), exact (generated)."""
        return self._h.rhs_jacobian(x, self._u(u), t, self._p(p))

    def jacobians(self, q, qd, u=None, t=0.0, p=None):
        """dF/dq, dF/dq', dF/du as a dict."""
        dq, dqd, du = self._h.jacobians(q, qd, self._u(u), t, self._p(p))
        return {"dF_dq": dq, "dF_dqd": dqd, "dF_du": du}

    def _evaluate_outputs(self, q, qd, u, t, p):
        return self._h.outputs(q, qd, self._u(u), t, self._p(p))

    def linear(self, op=None, p=None):
        """The linear model as `yamsc lin --json` computes it: M0, C0, K0, Q0, A, B
        about the model's `linearize` point moved by op ({"dof": v, "dof'": v,
        "input": v}, as --at), with q0, qd0, u0, residual, equilibrium_residual,
        modes; and C, D of the outputs (central differences)."""
        return self._h.linear(_assignments(op, "op"), [], self._p(p))

    def initial_state(self, ic=None):
        """x0 = [q, q'] from the model's `initial` block, overridden by ic (as --ic)."""
        return self._h.initial_state(_assignments(ic, "ic"))

    # -- simulation ------------------------------------------------------
    def simulate(self, tmax, dt, ic=None, u=None, method="rk4", rtol=None, atol=None, p=None,
                 frame=None):
        """Runs the model from t = 0 to tmax like `yamsc sim` (the same driver).

        ic: {"dof": v, "dof'": v} over the `initial` block, or x0 (2 nq values).
        u: None (zeros), {input: value} or nu values (constant), a table (rows of
        t and nu values, linear in t) or a callable u(t) returning nu values.
        dt: the step of rk4 and abm4, the output step of cvode; rtol and atol: cvode's
        tolerances, by default those of `yamsc sim` (1e-8, 1e-10). The GIL is released
        while the model runs (a callable u takes it back for each call).
        Returns a pandas DataFrame (columns as `yamsc sim -o` writes them) when
        pandas is present and frame is not False, else a dict of arrays.
        """
        if ic is None or isinstance(ic, dict):
            x0 = self.initial_state(ic)
        else:
            x0 = ic
        if isinstance(u, dict):
            u = self._u(u)
        rtol = _yamsc.DEFAULT_RTOL if rtol is None else rtol
        atol = _yamsc.DEFAULT_ATOL if atol is None else atol
        run = self._h.simulate(float(tmax), float(dt), x0, u, method, rtol, atol, self._p(p))
        columns = run["columns"]
        data = {columns[0]: run["time"]}
        nx = run["states"].shape[1]
        for j, name in enumerate(columns[1:1 + nx]):
            data[name] = run["states"][:, j]
        for j, name in enumerate(columns[1 + nx:]):
            data[name] = run["outputs"][:, j]
        pandas = _pandas(frame)
        if pandas is not None:
            df = pandas.DataFrame(data, copy=False)
            df.attrs["completed"] = run["completed"]
            return df
        return data


#: The routines of the model ABI; load(routines=SIMULATE) compiles what
#: rk4 runs need, as `yamsc sim` does.
ROUTINES = ("rhs", "rhs_jacobian", "mass_matrix", "forcing", "jacobians", "outputs")
SIMULATE = ("rhs", "outputs")


def load(path, sid=None, set=None, routines=None, external=None, aero=None, mooring=None,
         hydro=None, sea_state=None):
    """Checks and compiles a model file (cached like `yamsc sim`).

    sid: "body=file.sid,..." or {"body": "file.sid"} (as --sid); set: {name:
    value} over the parameters' defaults (as --set); routines: those to
    compile (default: all of ROUTINES; fewer compile faster for large models);
    external: the model's external functions, a shared library or a C/C++
    source (as --external; one implementation per function name and process);
    aero: a Cp/Ct/Cq table for the model's `load rotor_table` block, or an
    AeroDyn file for its `load blade_elements`, closed around the model as
    `yamsc sim --aero` closes it (its outputs follow the model's); mooring,
    hydro, sea_state: a MAP++ file for its `load mooring`, a HydroDyn file and
    its SeaState file for its `load hydrodyn` (as --mooring, --hydro,
    --sea-state). Raises yamsc.Error with the located diagnostics when the model has errors.
    """
    return Model(_yamsc.load(str(path), _sid_spec(sid), _assignments(set, "set"),
                             list(routines or ()), str(external or ""), str(aero or ""),
                             str(mooring or ""), str(hydro or ""), str(sea_state or "")))


def load_library(path, set=None):
    """A model library built beforehand (CMake, abi_export.hpp's YAMSC_EXPORT_MODEL)."""
    return Model(_yamsc.load_library(str(path), _assignments(set, "set")))
