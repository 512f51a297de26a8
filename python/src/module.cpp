// _yamsc: the C++ half of the Python package (python/yamsc/__init__.py is the
// other half). Arrays in are read in place when they are contiguous float64
// (forcecast converts anything else once); arrays out are new. Errors are
// yamsc.Error with yamsc's located messages; simulate() runs without the GIL.
#include "batch_functions.hpp"
#include "input_table.hpp"
#include "model_handle.hpp"

#include "analysis/constrained_model.hpp"

#include "diag/errors.hpp"

#include <yamsc/dynamic_model.hpp>
#include <yamsc/linear_view.hpp>
#include <yamsc/modal.hpp>
#include <yamsc/second_order.hpp>
#include <yamsc/simulation.hpp>

#include <pybind11/functional.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>

#include <sstream>
#include <string>
#include <tuple>
#include <vector>

namespace py = pybind11;
using yamsc::python::ModelHandle;

namespace {

using Array = py::array_t<double, py::array::c_style | py::array::forcecast>;
using OptArray = std::optional<Array>;
/// (name, primes, value): `psi' = 2` is ("psi", 1, 2.0); python/yamsc builds them.
using Assignments = std::vector<std::tuple<std::string, int, double>>;

std::vector<yamsc::driver::Assignment> assignments(const Assignments& a) {
    std::vector<yamsc::driver::Assignment> out;
    for (const auto& [name, primes, value] : a) out.push_back({name, primes, value});
    return out;
}

/// The data of `a`, which must hold n values; `fallback` (zeros) when a is None.
const double* data_of(const OptArray& a, int n, const char* what,
                      const std::vector<double>& fallback) {
    if (!a) return fallback.data();
    if (a->size() != n)
        throw py::value_error(std::string(what) + " must have " + std::to_string(n) +
                              " values, got " + std::to_string(a->size()));
    return n ? a->data() : fallback.data();
}

/// A new array that owns `v` (moved, not copied).
Array owning(std::vector<double>&& v, std::vector<py::ssize_t> shape) {
    auto* held = new std::vector<double>(std::move(v));
    py::capsule owner(held, [](void* p) { delete static_cast<std::vector<double>*>(p); });
    return Array(shape, held->data(), owner);
}

Array matrix(std::vector<double> v, int rows, int cols) {
    return owning(std::move(v), {rows, cols});
}

Array vector_of(std::vector<double> v) {
    const auto n = static_cast<py::ssize_t>(v.size());
    return owning(std::move(v), {n});
}

/// The arguments every evaluation shares: the view at p and zeros for what is not given.
struct Call {
    const yamsc::runtime::ModelView& v;
    std::vector<double> zeros;
    Call(ModelHandle& h, const OptArray& p)
        : v(h.view_at(data_of_params(h, p))),
          zeros(static_cast<std::size_t>(std::max(v.nx(), v.nu)) + 1, 0.0) {}
    static const double* data_of_params(const ModelHandle& h, const OptArray& p) {
        static const std::vector<double> none(1, 0.0);
        return p ? data_of(p, h.np(), "p", none) : nullptr;
    }
    const double* q(const OptArray& a) const { return data_of(a, v.nq, "q", zeros); }
    const double* qd(const OptArray& a) const { return data_of(a, v.nq, "qd", zeros); }
    const double* x(const OptArray& a) const { return data_of(a, v.nx(), "x", zeros); }
    const double* u(const OptArray& a) const { return data_of(a, v.nu, "u", zeros); }
};

template <class F> void require(const F& routine, const char* name) {
    if (!routine)
        throw py::value_error(std::string("the model was loaded without its ") + name +
                              " routine (yamsc.load(..., routines=...))");
}

py::list modes_of(const std::vector<yamsc::runtime::Mode>& modes) {
    py::list out;
    for (const yamsc::runtime::Mode& m : modes) {
        py::dict d;
        d["freq_hz"] = m.freq_hz;
        d["damping_ratio"] = m.damping_ratio;
        d["rigid_body"] = m.rigid_body;
        out.append(d);
    }
    return out;
}

/// linear() of a model with constraints: in its independent coordinates and
/// speeds (runtime::reduced_linear_model, docs/constraints.md).
py::dict constrained_linear(const yamsc::runtime::ModelView& v, std::vector<double> q,
                            std::vector<double> qd, const std::vector<double>& u) {
    std::vector<double> x = q;
    x.insert(x.end(), qd.begin(), qd.end());
    x.insert(x.end(), v.block_initial_states.begin(), v.block_initial_states.end());
    std::ostringstream quiet;
    yamsc::analysis::consistent_start(v, 0.0, x, u, false, quiet);
    const yamsc::runtime::ReducedLinearModel m = yamsc::analysis::located_constraint_errors(
        v, [&] { return yamsc::runtime::reduced_linear_model(v, x, u); });
    const int ns = static_cast<int>(m.state_names.size()), mq = m.n_coordinates;
    py::dict out;
    out["states"] = m.state_names;
    out["A"] = matrix(m.A, ns, ns);
    out["B"] = matrix(m.B, ns, v.nu);
    out["T"] = matrix(m.T, v.nx(), ns);
    if (m.second_order && !m.M.empty()) {
        out["M"] = matrix(m.M, mq, mq);
        out["C"] = matrix(m.C, mq, mq);
        out["K"] = matrix(m.K, mq, mq);
    }
    out["q0"] = vector_of(std::vector<double>(x.begin(), x.begin() + v.nq));
    out["qd0"] = vector_of(std::vector<double>(x.begin() + v.nq, x.begin() + 2 * v.nq));
    out["u0"] = vector_of(u);
    out["modes"] = modes_of(m.modes);
    return out;
}

py::dict linear(ModelHandle& h, const Assignments& at, const Assignments& u_given,
                const OptArray& p) {
    Call c(h, p);
    std::vector<double> q, qd, u;
    yamsc::analysis::operating_point(h.loaded(), h.params_at(p ? p->data() : nullptr),
                                     assignments(at), assignments(u_given), q, qd, u);
    if (c.v.nc > 0) return constrained_linear(c.v, q, qd, u);
    const yamsc::runtime::SecondOrderModel lm =
        yamsc::runtime::second_order_model(c.v, q, qd, u, 0.0);
    std::vector<double> x0 = q;
    x0.insert(x0.end(), qd.begin(), qd.end());
    const int nq = lm.nq, nu = lm.nu, ny = c.v.ny;
    py::dict out;
    out["M0"] = matrix(lm.M0, nq, nq);
    out["C0"] = matrix(lm.C0, nq, nq);
    out["K0"] = matrix(lm.K0, nq, nq);
    out["Q0"] = matrix(lm.Q0, nq, nu);
    out["A"] = matrix(lm.A, 2 * nq, 2 * nq);
    out["B"] = matrix(lm.B, 2 * nq, nu);
    if (c.v.outputs) {
        yamsc::runtime::OutputMatrices cd = yamsc::runtime::output_matrices(c.v, x0, u, 0.0);
        out["C"] = matrix(std::move(cd.C), ny, 2 * nq);
        out["D"] = matrix(std::move(cd.D), ny, nu);
    }
    out["q0"] = vector_of(q);
    out["qd0"] = vector_of(qd);
    out["u0"] = vector_of(u);
    out["residual"] = vector_of(lm.F0);
    out["equilibrium_residual"] = lm.equilibrium_residual;
    out["modes"] = modes_of(lm.modes);
    return out;
}

/// The inputs of a run: None (zeros), nu constants, a table (rows of t and
/// nu values) or a callable u(t) -> nu values, called with the GIL held.
void set_inputs(yamsc::runtime::SimulationOptions& s, const py::object& u, int nu) {
    s.u.assign(static_cast<std::size_t>(nu), 0.0);
    if (u.is_none()) return;
    if (PyCallable_Check(u.ptr())) {
        py::function f = u;
        s.u_of_t = [f, nu](double t, double* out) {
            py::gil_scoped_acquire gil;
            Array a = Array::ensure(f(t));
            if (!a || a.size() != nu)
                throw py::value_error("u(t) must return " + std::to_string(nu) + " values");
            std::copy(a.data(), a.data() + nu, out);
        };
        return;
    }
    Array a = Array::ensure(u);
    if (!a) throw py::type_error("u must be None, an array or a callable u(t)");
    if (a.ndim() == 2) {
        if (a.shape(1) != nu + 1)
            throw py::value_error("an input table has 1 + " + std::to_string(nu) + " columns");
        s.u_of_t = yamsc::python::table_input(std::vector<double>(a.data(), a.data() + a.size()),
                                              static_cast<int>(a.shape(0)), nu);
        return;
    }
    s.u.assign(data_of(a, nu, "u", s.u), data_of(a, nu, "u", s.u) + nu);
}

py::dict simulate(ModelHandle& h, double t_end, double dt, const OptArray& x0, const py::object& u,
                  const std::string& method, double rtol, double atol, const OptArray& p) {
    // A copy: the run uses it without the GIL while other calls may rebind.
    const yamsc::runtime::ModelView v = Call(h, p).v;
    yamsc::runtime::SimulationOptions s;
    s.t_end = t_end;
    s.dt = dt;
    const auto m = yamsc::runtime::parse_method(method);
    if (!m) throw py::value_error("method must be 'rk4', 'abm4' or 'cvode', not '" + method + "'");
    s.method = *m;
    s.rtol = rtol;
    s.atol = atol;
    std::vector<double> zeros(static_cast<std::size_t>(v.nx()) + 1, 0.0);
    const double* x = data_of(x0, v.nx(), "x0", zeros);
    s.x0.assign(x, x + v.nx());
    set_inputs(s, u, v.nu);
    if (v.nc > 0) {
        // On the constraints from the start, as `yamsc sim` (docs/constraints.md).
        std::vector<double> u0 = s.u;
        if (s.u_of_t) s.u_of_t(0.0, u0.data());
        std::ostringstream quiet;
        yamsc::analysis::consistent_start(v, 0.0, s.x0, u0, false, quiet);
    }
    bool interrupted = false;
    // Ctrl-C stops the run: Python's signal handlers need the GIL to run.
    auto progress = [&interrupted](double, double) {
        py::gil_scoped_acquire gil;
        interrupted = PyErr_CheckSignals() != 0;
        return !interrupted;
    };
    yamsc::runtime::SimulationResult r;
    {
        py::gil_scoped_release released;
        r = yamsc::runtime::simulate(v, s, progress);
    }
    if (interrupted) throw py::error_already_set();
    const auto rows = static_cast<py::ssize_t>(r.rows());
    py::dict out;
    out["columns"] = r.columns;
    out["time"] = vector_of(std::move(r.time));
    out["states"] = owning(std::move(r.states), {rows, r.nx});
    out["outputs"] = owning(std::move(r.outputs), {rows, r.ny});
    out["completed"] = r.completed;
    return out;
}

} // namespace

PYBIND11_MODULE(_yamsc, mod) {
    mod.doc() = "yamsc models from Python: the compiled part (see the yamsc package)";
    static py::exception<yamsc::python::LoadError> error(mod, "Error", PyExc_RuntimeError);
    py::register_exception_translator([](std::exception_ptr e) {
        try {
            if (e) std::rethrow_exception(e);
        } catch (const yamsc::python::LoadError& x) {
            error(x.what());
        } catch (const yamsc::diag::UserError& x) {
            error(x.what());
        } catch (const yamsc::diag::UsageError& x) {
            error(x.what());
        } catch (const yamsc::runtime::SharedModelError& x) {
            error(x.what());
        }
    });

    // `yamsc sim`'s tolerances, so that simulate() defaults to the same run.
    mod.attr("DEFAULT_RTOL") = yamsc::driver::SimOptions{}.rtol;
    mod.attr("DEFAULT_ATOL") = yamsc::driver::SimOptions{}.atol;

    py::class_<yamsc::python::Described>(mod, "Described")
        .def_readonly("name", &yamsc::python::Described::name)
        .def_readonly("doc", &yamsc::python::Described::doc)
        .def_readonly("unit", &yamsc::python::Described::unit);

    py::class_<ModelHandle>(mod, "Model")
        .def_property_readonly("name",
                               [](const ModelHandle& h) {
                                   const auto& m = h.loaded().front.model;
                                   return m ? m->name : std::string();
                               })
        .def_property_readonly("library_path",
                               [](const ModelHandle& h) { return h.library().path(); })
        .def_property_readonly("nq", [](const ModelHandle& h) { return h.view().nq; })
        .def_property_readonly("nu", [](const ModelHandle& h) { return h.view().nu; })
        .def_property_readonly("ny", [](const ModelHandle& h) { return h.view().ny; })
        .def_property_readonly("np", &ModelHandle::np)
        .def_property_readonly("params",
                               [](const ModelHandle& h) { return vector_of(h.loaded().params); })
        .def_property_readonly(
            "default_params",
            [](const ModelHandle& h) { return vector_of(h.library().default_params()); })
        .def("described", &ModelHandle::described, py::arg("kind"))
        .def(
            "mass_matrix",
            [](ModelHandle& h, const OptArray& q, const OptArray& u, double t, const OptArray& p) {
                Call c(h, p);
                require(c.v.mass_matrix, "mass_matrix");
                Array M({c.v.nq, c.v.nq});
                c.v.mass_matrix(t, c.q(q), c.u(u), M.mutable_data());
                return M;
            },
            py::arg("q"), py::arg("u"), py::arg("t"), py::arg("p"))
        .def(
            "forcing",
            [](ModelHandle& h, const OptArray& q, const OptArray& qd, const OptArray& u, double t,
               const OptArray& p) {
                Call c(h, p);
                require(c.v.forcing, "forcing");
                Array F(c.v.nq);
                c.v.forcing(t, c.q(q), c.qd(qd), c.u(u), F.mutable_data());
                return F;
            },
            py::arg("q"), py::arg("qd"), py::arg("u"), py::arg("t"), py::arg("p"))
        .def(
            "rhs",
            [](ModelHandle& h, const OptArray& x, const OptArray& u, double t, const OptArray& p) {
                Call c(h, p);
                Array xdot(c.v.nx());
                c.v.rhs(t, c.x(x), c.u(u), xdot.mutable_data());
                return xdot;
            },
            py::arg("x"), py::arg("u"), py::arg("t"), py::arg("p"))
        .def(
            "rhs_jacobian",
            [](ModelHandle& h, const OptArray& x, const OptArray& u, double t, const OptArray& p) {
                Call c(h, p);
                require(c.v.rhs_jacobian, "rhs_jacobian");
                Array J({c.v.nx(), c.v.nx()});
                c.v.rhs_jacobian(t, c.x(x), c.u(u), J.mutable_data());
                return J;
            },
            py::arg("x"), py::arg("u"), py::arg("t"), py::arg("p"))
        .def(
            "jacobians",
            [](ModelHandle& h, const OptArray& q, const OptArray& qd, const OptArray& u, double t,
               const OptArray& p) {
                Call c(h, p);
                require(c.v.jacobians, "jacobians");
                const int nq = c.v.nq, nu = c.v.nu;
                Array dq({nq, nq}), dqd({nq, nq}), du({nq, nu});
                // One spare row: nu = 0 still passes a writable pointer.
                std::vector<double> du_data(static_cast<std::size_t>(nq * nu) + 1);
                c.v.jacobians(t, c.q(q), c.qd(qd), c.u(u), dq.mutable_data(), dqd.mutable_data(),
                              du_data.data());
                std::copy(du_data.begin(), du_data.end() - 1, du.mutable_data());
                return py::make_tuple(dq, dqd, du);
            },
            py::arg("q"), py::arg("qd"), py::arg("u"), py::arg("t"), py::arg("p"))
        .def(
            "outputs",
            [](ModelHandle& h, const OptArray& q, const OptArray& qd, const OptArray& u, double t,
               const OptArray& p) {
                Call c(h, p);
                require(c.v.outputs, "outputs");
                std::vector<double> y(static_cast<std::size_t>(c.v.ny) + 1);
                c.v.outputs(t, c.q(q), c.qd(qd), c.u(u), y.data());
                y.pop_back();
                return vector_of(std::move(y));
            },
            py::arg("q"), py::arg("qd"), py::arg("u"), py::arg("t"), py::arg("p"))
        .def("linear", &linear, py::arg("at"), py::arg("u"), py::arg("p"))
        .def(
            "initial_state",
            [](const ModelHandle& h, const Assignments& ic) {
                std::vector<double> q, qd;
                yamsc::analysis::initial_state(h.loaded(), assignments(ic), q, qd);
                q.insert(q.end(), qd.begin(), qd.end());
                return vector_of(std::move(q));
            },
            py::arg("ic"))
        .def("simulate", &simulate, py::arg("t_end"), py::arg("dt"), py::arg("x0"), py::arg("u"),
             py::arg("method"), py::arg("rtol"), py::arg("atol"), py::arg("p"));

    mod.def(
        "load",
        [](const std::string& path, const std::string& sid, const Assignments& set,
           const std::vector<std::string>& routines, const std::string& external,
           const std::string& aero, const std::string& mooring, const std::string& hydro,
           const std::string& sea_state) {
            const auto a = assignments(set);
            py::gil_scoped_release released; // compiling can take seconds
            yamsc::analysis::BlockOptions blocks;
            blocks.aero = aero;
            blocks.mooring = mooring;
            blocks.hydro = hydro;
            blocks.sea_state = sea_state;
            return ModelHandle::from_source(path, sid, a, routines, external, blocks);
        },
        py::arg("path"), py::arg("sid"), py::arg("set"), py::arg("routines"),
        py::arg("external") = std::string(), py::arg("aero") = std::string(),
        py::arg("mooring") = std::string(), py::arg("hydro") = std::string(),
        py::arg("sea_state") = std::string());
    mod.def(
        "load_library",
        [](const std::string& path, const Assignments& set) {
            return ModelHandle::from_library(path, assignments(set));
        },
        py::arg("path"), py::arg("set"));
    yamsc::python::add_batch_functions(mod);
}
