"""The Python module against the yamsc executable of the same build: the same
numbers to the last bit (lin --json; eval where it rounds as the compiled code
does) or to the last digit written (sim's CSV), located errors, and
simulations that run without the GIL."""
import threading
import time

import numpy as np
import pytest

import yamsc

Q = [0.3, -0.2]
QD = [0.1, 0.4]


@pytest.fixture(scope="module")
def pendulum(models):
    return yamsc.load(models / "double_pendulum.mbd")


@pytest.fixture(scope="module")
def turbine(models):
    return yamsc.load(models / "nrel5mw_land_3dof.mbd")


def test_names_units_defaults(pendulum):
    assert [d.name for d in pendulum.dofs] == ["th1", "th2"]
    assert [u.name for u in pendulum.inputs] == ["tau", "f"]
    assert [o.name for o in pendulum.outputs] == ["x_tip", "z_tip", "v_tip"]
    m1 = pendulum.params[0]
    assert (m1.name, m1.unit, m1.default, m1.value) == ("m1", "kg", 2.0, 2.0)
    assert pendulum.dofs[0].unit == "rad"
    assert pendulum.outputs[2].unit == "m/s"


def test_evaluation_equals_eval(pendulum, models, cli):
    ref = cli("eval", models / "double_pendulum.mbd", "--q", "0.3,-0.2", "--qd", "0.1,0.4",
              "--u", "tau=1,f=0.5", "--set", "k=8", "--json", parse_json=True)
    q, qd, u = np.array(Q), np.array(QD), np.array([1.0, 0.5])
    p = {"k": 8.0}
    np.testing.assert_array_equal(pendulum.mass_matrix(q, p), ref["M"])
    np.testing.assert_array_equal(pendulum.forcing(q, qd, u, 0.0, p), ref["F"])
    np.testing.assert_array_equal(pendulum.outputs(q, qd, u, p=p), ref["y"])
    # rhs is [q', M^-1 F]
    xdot = pendulum.rhs(np.concatenate([q, qd]), u, p=p)
    np.testing.assert_array_equal(xdot[:2], qd)
    np.testing.assert_allclose(xdot[2:], np.linalg.solve(ref["M"], ref["F"]), rtol=1e-12)
    # Parameters given as an array, and inputs by name, are the same call.
    values = pendulum.param_values.copy()
    values[[q.name for q in pendulum.params].index("k")] = 8.0
    np.testing.assert_array_equal(pendulum.forcing(q, qd, {"tau": 1.0, "f": 0.5}, 0.0, values),
                                  ref["F"])


@pytest.mark.parametrize("model", ["nrel5mw_land_2dof", "nrel5mw_land_3dof"])
def test_turbine_evaluation_equals_eval(models, cli, model):
    m = yamsc.load(models / f"{model}.mbd")
    q = np.linspace(0.05, 0.2, m.nq)
    qd = np.linspace(-0.1, 0.3, m.nq)
    u = np.linspace(1e5, 4e6, m.nu)
    ref = cli("eval", models / f"{model}.mbd", "--q", ",".join(map(repr, q)),
              "--qd", ",".join(map(repr, qd)),
              "--u", ",".join(f"{i.name}={v!r}" for i, v in zip(m.inputs, u)), "--t", 0.5,
              "--json", parse_json=True)
    # `yamsc eval` interprets the IR; the module runs the compiled code (that of
    # sim and lin), which rounds a few sums of the turbines differently: 6e-15
    # relative at most, measured.
    for ours, theirs in ((m.mass_matrix(q, u=u, t=0.5), ref["M"]),
                         (m.forcing(q, qd, u, 0.5), ref["F"]), (m.outputs(q, qd, u, 0.5), ref["y"])):
        theirs = np.array(theirs)
        np.testing.assert_allclose(ours, theirs, rtol=0, atol=2e-14 * np.abs(theirs).max())
    # `yamsc eval --compiled` runs the same compiled code: equal to the last bit.
    compiled = cli("eval", models / f"{model}.mbd", "--compiled", "--q", ",".join(map(repr, q)),
                   "--qd", ",".join(map(repr, qd)),
                   "--u", ",".join(f"{i.name}={v!r}" for i, v in zip(m.inputs, u)), "--t", 0.5,
                   "--json", parse_json=True)
    assert np.array_equal(m.mass_matrix(q, u=u, t=0.5), np.array(compiled["M"]))
    assert np.array_equal(m.forcing(q, qd, u, 0.5), np.array(compiled["F"]))
    assert np.array_equal(m.outputs(q, qd, u, 0.5), np.array(compiled["y"]))


def test_jacobians_agree_with_differences(pendulum):
    q, qd, u = np.array(Q), np.array(QD), np.array([1.0, 0.5])
    J = pendulum.jacobians(q, qd, u)
    h = 1e-6
    for k in range(2):
        dq = np.zeros(2)
        dq[k] = h
        diff = (pendulum.forcing(q + dq, qd, u) - pendulum.forcing(q - dq, qd, u)) / (2 * h)
        np.testing.assert_allclose(J["dF_dq"][:, k], diff, rtol=1e-7, atol=1e-8)
    np.testing.assert_array_equal(J["dF_du"][:, 0], [1.0, 0.0])  # tau acts on th1 only


@pytest.mark.parametrize("model,at", [("nrel5mw_land_3dof", {"q1": 0.1}),
                                      ("nrel5mw_land_2dof", {"psi'": 1.2, "tau_g": 4e6}),
                                      ("double_pendulum", {"th1": 0.3, "th2'": 0.2})])
def test_linear_equals_lin(models, cli, model, at):
    ref = cli("lin", models / f"{model}.mbd", "--json", "--at",
              ",".join(f"{k}={v!r}" for k, v in at.items()), parse_json=True)
    m = yamsc.load(models / f"{model}.mbd")
    lin = m.linear(at)
    for key in ("M0", "C0", "K0", "Q0", "A", "B"):
        np.testing.assert_array_equal(lin[key], ref[key], err_msg=key)
    for key in ("q0", "qd0", "u0", "residual"):
        np.testing.assert_array_equal(lin[key], ref[key], err_msg=key)
    assert lin["equilibrium_residual"] == ref["equilibrium_residual"]
    assert [m["freq_hz"] for m in lin["modes"]] == [m["freq_hz"] for m in ref["modes"]]
    assert lin["C"].shape == (m.ny, 2 * m.nq) and lin["D"].shape == (m.ny, m.nu)


def test_output_matrices(pendulum):
    lin = pendulum.linear()
    # x_tip = -L1 sin th1 - L2 sin(th1 + th2) (links hang along -z, rotate about y):
    # at rest, dx/dth1 = -1.8, dx/dth2 = -0.8.
    np.testing.assert_allclose(lin["C"][0], [-1.8, -0.8, 0, 0], atol=1e-9)
    np.testing.assert_allclose(lin["D"], np.zeros((3, 2)), atol=1e-12)


def _csv(text):
    lines = text.strip().splitlines()
    return lines[0].split(","), [line.split(",") for line in lines[1:]]


@pytest.mark.parametrize("method", ["rk4", "cvode"])
def test_simulate_equals_sim(pendulum, models, cli, tmp_path, method):
    out = tmp_path / "run.csv"
    cli("sim", models / "double_pendulum.mbd", "--tmax", 2, "--dt", 0.01, "--u", "tau=1",
        "--ic", "th1=0.5", "--method", method, "-o", out)
    header, rows = _csv(out.read_text())
    run = pendulum.simulate(2.0, 0.01, ic={"th1": 0.5}, u={"tau": 1.0}, method=method)
    assert list(run.columns) == header == pendulum.columns()
    assert len(run) == len(rows)
    # The CSV holds 10 significant digits (runtime/include/yamsc/csv.hpp).
    ours = [[format(v, ".10g") for v in row] for row in run.to_numpy()]
    assert ours == rows


def test_simulate_turbine_equals_sim(turbine, models, cli, tmp_path):
    out = tmp_path / "run.csv"
    cli("sim", models / "nrel5mw_land_3dof.mbd", "--tmax", 1, "--dt", 0.01,
        "--u", "f_a=5e5,tau_a=4e6", "-o", out)
    header, rows = _csv(out.read_text())
    run = turbine.simulate(1.0, 0.01, u={"f_a": 5e5, "tau_a": 4e6}, frame=False)
    assert list(run) == header
    ours = [[format(run[c][i], ".10g") for c in header] for i in range(len(rows))]
    assert ours == rows


def test_rotor_block_equals_sim_aero(models, cli, tmp_path):
    """load(aero=TABLE) closes the model's `load rotor_table` block as `sim --aero` does."""
    table = models / "data" / "Cp_Ct_Cq.NREL5MW.txt"
    out = tmp_path / "run.csv"
    cli("sim", models / "nrel5mw_land_operating.mbd", "--aero", table, "--tmax", 0.5, "--dt", 0.01,
        "--u", "V_wind=11,gen_torque=40000", "-o", out)
    header, rows = _csv(out.read_text())
    m = yamsc.load(models / "nrel5mw_land_operating.mbd", aero=table)
    run = m.simulate(0.5, 0.01, u={"V_wind": 11.0, "gen_torque": 4e4}, frame=False)
    assert "aero_thrust" in header and list(run) == header
    ours = [[format(run[c][i], ".10g") for c in header] for i in range(len(rows))]
    assert ours == rows
    thrust = float(rows[0][header.index("aero_thrust")])
    assert 3e5 < thrust < 9e5  # the table's thrust at about 11 m/s, not the input's 0


def test_rotor_block_needs_the_declaration(models, tmp_path):
    with pytest.raises(yamsc.Error, match="declares no `load rotor_table` or `load blade_elements` block"):
        yamsc.load(models / "double_pendulum.mbd",
                   aero=models / "data" / "Cp_Ct_Cq.NREL5MW.txt")


def test_inputs_constant_table_callable(pendulum):
    kw = dict(ic={"th1": 0.2}, frame=False)
    constant = pendulum.simulate(1.0, 0.01, u=np.array([1.0, 0.0]), **kw)
    table = pendulum.simulate(1.0, 0.01, u=np.array([[0.0, 1.0, 0.0], [5.0, 1.0, 0.0]]), **kw)
    called = pendulum.simulate(1.0, 0.01, u=lambda t: [1.0, 0.0], **kw)
    for name in constant:
        np.testing.assert_array_equal(table[name], constant[name])
        np.testing.assert_array_equal(called[name], constant[name])


def test_input_ramp_table(pendulum):
    """A table is linear in time between its rows and held after the last."""
    table = np.array([[0.0, 0.0, 0.0], [0.5, 2.0, -1.0], [0.8, 2.0, -1.0]])
    ramp = lambda t: [np.interp(t, table[:, 0], table[:, 1]), np.interp(t, table[:, 0], table[:, 2])]
    kw = dict(method="cvode", frame=False)
    a = pendulum.simulate(1.0, 0.01, u=table, **kw)
    b = pendulum.simulate(1.0, 0.01, u=ramp, **kw)
    np.testing.assert_allclose(a["th1"], b["th1"], rtol=1e-6, atol=1e-9)
    assert abs(a["th1"][-1]) > 0.05  # the inputs did move the pendulum


def test_arrays_of_other_types_are_converted(pendulum):
    q32 = np.array(Q, dtype=np.float32)
    np.testing.assert_array_equal(pendulum.mass_matrix(q32), pendulum.mass_matrix(q32.astype(float)))
    strided = np.array([0.3, 9.0, -0.2, 9.0])[::2]
    np.testing.assert_array_equal(pendulum.mass_matrix(strided), pendulum.mass_matrix(np.array(Q)))
    with pytest.raises(ValueError, match="q must have 2 values"):
        pendulum.mass_matrix(np.zeros(3))


def test_load_library_built_from_generated_code(pendulum, models, source_dir, cli, tmp_path):
    """A library as a build system makes one: yamsc's C++, the ABI shim, c++ -shared."""
    import os
    import subprocess
    cli(models / "double_pendulum.mbd", "-o", tmp_path / "dp.cpp", "--header", tmp_path / "dp.hpp")
    (tmp_path / "abi.cpp").write_text(
        '#include "dp.hpp"\n#include <yamsc/abi_export.hpp>\nYAMSC_EXPORT_MODEL(double_pendulum)\n')
    cxx = os.environ.get("YAMSC_CXX") or os.environ.get("CXX") or "c++"
    subprocess.run([cxx, "-std=c++17", "-O2", "-shared", "-fPIC", "-fvisibility=hidden",
                    "-I", str(source_dir / "runtime" / "include"), "-I", str(tmp_path),
                    str(tmp_path / "dp.cpp"), str(tmp_path / "abi.cpp"),
                    "-o", str(tmp_path / "libdp.so")], check=True)
    lib = yamsc.load_library(tmp_path / "libdp.so")
    x = np.array(Q + QD)
    np.testing.assert_array_equal(lib.rhs(x, [1.0, 0.5]), pendulum.rhs(x, [1.0, 0.5]))
    assert lib.params[0].default == 2.0 and lib.name == ""
    run = lib.simulate(1.0, 0.01, ic=np.array([0.5, 0, 0, 0]), frame=False)
    np.testing.assert_array_equal(
        run["th1"], pendulum.simulate(1.0, 0.01, ic={"th1": 0.5}, frame=False)["th1"])


def test_fewer_routines(models):
    m = yamsc.load(models / "double_pendulum.mbd", routines=yamsc.SIMULATE)
    assert m.simulate(0.1, 0.01, frame=False)["th1"].shape == (11,)
    with pytest.raises(ValueError, match="loaded without its mass_matrix routine"):
        m.mass_matrix(np.zeros(2))
    with pytest.raises(yamsc.Error, match="no routine .nope."):
        yamsc.load(models / "double_pendulum.mbd", routines=["nope"])


def test_load_library(pendulum):
    lib = yamsc.load_library(pendulum.library_path, set={"k": 8.0})
    assert [d.name for d in lib.dofs] == ["th1", "th2"]
    q, qd = np.array(Q), np.array(QD)
    np.testing.assert_array_equal(lib.forcing(q, qd), pendulum.forcing(q, qd, p={"k": 8.0}))


def test_located_errors(tmp_path):
    bad = tmp_path / "bad.mbd"
    bad.write_text("model bad\ndof a\nrigid b { mass = 1; com = (0, 0, nope) }\n"
                   "joint ground -> b { rotate y a }\n")
    with pytest.raises(yamsc.Error, match=r"bad\.mbd:3:\d+: error: .*nope"):
        yamsc.load(bad)
    with pytest.raises(yamsc.Error, match="cannot load model library"):
        yamsc.load_library(tmp_path / "missing.so")


def test_unknown_names(pendulum, models):
    with pytest.raises(yamsc.Error, match="unknown parameter"):
        yamsc.load(models / "double_pendulum.mbd", set={"kk": 1})
    with pytest.raises(yamsc.Error, match="unknown"):
        pendulum.linear({"th9": 1})


def test_simulation_releases_the_gil(pendulum):
    """Two runs in threads finish with the same numbers while a third thread,
    pure Python, keeps running: it could not if the runs held the GIL."""
    results, count, done = [], [0], threading.Event()

    def count_while_running():
        while not done.is_set():
            count[0] += 1

    def run():
        results.append(pendulum.simulate(20.0, 1e-4, ic={"th1": 0.5}, frame=False))

    counter = threading.Thread(target=count_while_running)
    runs = [threading.Thread(target=run) for _ in range(2)]
    counter.start()
    start = time.perf_counter()
    for t in runs:
        t.start()
    for t in runs:
        t.join()
    elapsed = time.perf_counter() - start
    done.set()
    counter.join()
    assert len(results) == 2
    np.testing.assert_array_equal(results[0]["th1"], results[1]["th1"])
    # A Python loop counts millions per second; holding the GIL in the runs
    # would leave it the ~1 % progress checks only.
    assert count[0] > 100_000 * elapsed, (count[0], elapsed)


def test_ctrl_c_stops_a_run(pendulum):
    """SIGINT (here interrupt_main) stops a run at its next progress check
    (every 1 %); the whole run would take about 25 s."""
    import _thread
    threading.Timer(0.3, _thread.interrupt_main).start()
    start = time.perf_counter()
    with pytest.raises(KeyboardInterrupt):
        pendulum.simulate(1e5, 1.0, ic={"th1": 0.5}, method="cvode", frame=False)
    assert time.perf_counter() - start < 10


def test_cache_key_holds_the_module_build(models, cli, tmp_path, monkeypatch):
    """The module and yamsc compile the same routines into separate entries:
    the key names the build that derived the code (analysis/jit_cache.cpp)."""
    monkeypatch.setenv("YAMSC_CACHE_DIR", str(tmp_path))
    m = yamsc.load(models / "double_pendulum.mbd", routines=yamsc.SIMULATE)
    assert m.library_path.startswith(str(tmp_path))
    yamsc.load(models / "double_pendulum.mbd", routines=yamsc.SIMULATE)  # a hit
    assert len(list(tmp_path.glob("double_pendulum-*.so"))) == 1
    cli("sim", models / "double_pendulum.mbd", "--tmax", 0.1, "--dt", 0.01)
    assert len(list(tmp_path.glob("double_pendulum-*.so"))) == 2


def test_external_functions(source_dir):
    """A model with external loads (tests/external): its C source compiled with it;
    the Jacobian of rhs equals central differences through the user's functions."""
    folder = source_dir / "tests" / "external" / "models"
    m = yamsc.load(folder / "ext_pendulum.mbd", external=folder / "pendulum_loads.c",
                   set={"P": 0.5})
    x, u = np.array([0.3, -0.2]), np.array([0.1])
    J = m.rhs_jacobian(x, u)
    h = 1e-6
    for k in range(2):
        dx = np.zeros(2)
        dx[k] = h
        diff = (m.rhs(x + dx, u) - m.rhs(x - dx, u)) / (2 * h)
        np.testing.assert_allclose(J[:, k], diff, rtol=1e-6, atol=1e-8)
    with pytest.raises(yamsc.Error, match="has no implementation"):
        yamsc.load(folder / "ext_pendulum.mbd")


def test_constrained_model_equals_sim_and_lin(models, cli, tmp_path):
    # The four-bar's loop is kept by the same constrained view as `yamsc sim`
    # and `lin`: the same consistent start, projection and reduced model.
    model = models / "four_bar.mbd"
    m = yamsc.load(model)
    out = tmp_path / "run.csv"
    cli("sim", model, "--tmax", 1, "--dt", 0.01, "-o", out)
    header, rows = _csv(out.read_text())
    run = m.simulate(1.0, 0.01)
    assert list(run.columns) == header
    assert "lambda:pin.x" in header and "constraint_position_error" in header
    ours = [[format(v, ".10g") for v in row] for row in run.to_numpy()]
    assert ours == rows
    errors = run["constraint_position_error"].to_numpy()
    assert errors.max() < 1e-10

    at = {"th2": 0.3, "phi3": 0.4, "th4": 1.4}
    ref = cli("lin", model, "--json", "--at", ",".join(f"{k}={v!r}" for k, v in at.items()),
              parse_json=True)
    lin = m.linear(at)
    for key in ("A", "B", "T", "M", "C", "K", "q0", "qd0"):
        np.testing.assert_array_equal(lin[key], ref[key], err_msg=key)
    assert [x["freq_hz"] for x in lin["modes"]] == [x["freq_hz"] for x in ref["modes"]]
    # One independent coordinate and speed: the crank's.
    assert np.asarray(lin["A"]).shape == (2, 2)
