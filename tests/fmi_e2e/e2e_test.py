"""End to end: `yamsc fmu` units driven by our own FMI host (fmi_host.py)
against `yamsc sim`. Co-simulation with RK4 at sim's step equals sim's CSV to
1e-9; model exchange under the host's RK4 at that step to 1e-6; the
description passes the structural checks; the binary exports the FMI
functions only; the directional derivatives equal central differences; a
state saved and restored repeats a step exactly.

usage: e2e_test.py YAMSC SOURCE_DIR WORK_DIR [CASE...]"""

import csv
import math
import os
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import fmi_host  # noqa: E402

YAMSC, SOURCE, WORK = sys.argv[1:4]
WANTED = sys.argv[4:]
failures = []


def run(*args):
    r = subprocess.run([YAMSC] + list(args), capture_output=True, text=True)
    if r.returncode != 0:
        raise SystemExit("yamsc %s failed (%d):\n%s%s" % (" ".join(args), r.returncode, r.stdout,
                                                          r.stderr))
    return r.stdout


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in row] for row in rows[1:]]


def check(what, ok, detail=""):
    print("%s %s %s" % ("ok  " if ok else "FAIL", what, detail))
    if not ok:
        failures.append(what)


def compare(what, unit, record, rows, header, sim_rows, tolerance):
    names = [unit.description.by_vr[vr].name for vr in record]
    columns = {n: header.index(n) for n in names if n in header}
    check(what + ": every state and output is a column of sim's CSV",
          len(columns) == len(names), str(sorted(set(names) - set(columns))))
    check(what + ": as many rows as sim's", len(rows) == len(sim_rows),
          "%d vs %d" % (len(rows), len(sim_rows)))
    worst, where = 0.0, ""
    for row, ref in zip(rows, sim_rows):
        if abs(row[0] - ref[0]) > 1e-12:
            check(what + ": the same times", False, "%g vs %g" % (row[0], ref[0]))
            return
        for k, name in enumerate(names):
            if name not in columns:
                continue
            # sim's CSV has 10 significant digits: relative to the value's size.
            error = abs(row[k + 1] - ref[columns[name]]) / max(1.0, abs(ref[columns[name]]))
            if error > worst:
                worst, where = error, "%s at t = %g" % (name, row[0])
    check(what + ": equals sim to %g" % tolerance, worst <= tolerance,
          "(largest difference %.3g, %s)" % (worst, where))
    return worst


def structural(unit, what):
    d = unit.description
    symbols = unit.exported()
    if symbols is not None:
        others = [s for s in symbols if not s.startswith(("fmi2", "fmi3"))]
        check(what + ": the binary exports the FMI functions only", not others, str(others[:5]))
        prefix = "fmi3" if d.fmi3 else "fmi2"
        needed = ["DoStep", "GetDirectionalDerivative", "SetContinuousStates",
                  "GetFMUState" if d.fmi3 else "GetFMUstate"]
        check(what + ": the functions the description promises are there",
              all(prefix + n in symbols for n in needed))


def planted_errors(unit, what):
    """The host's structural checks reject descriptions with planted faults."""
    with open(os.path.join(unit.folder, "modelDescription.xml"), "rb") as f:
        text = f.read().decode()
    d = unit.description
    q = d.by_vr[d.states[0]]
    faults = {
        "a value reference twice": ('valueReference="%d"' % (q.vr + 1), 'valueReference="%d"' % q.vr),
        "a parameter that is continuous": ('causality="parameter" variability="tunable"',
                                           'causality="parameter" variability="continuous"'),
        "an output with a start value": (
            ('causality="output" variability="continuous" initial="calculated"',
             'causality="output" variability="continuous" initial="calculated" start="1"')
            if d.fmi3 else ('<Real unit="m"/>', '<Real unit="m" start="1"/>')),
        "a unit not defined": ('unit="rad"', 'unit="furlong"'),
    }
    if d.fmi3:
        faults["a derivative of nothing"] = ('derivative="%d"' % q.vr, 'derivative="999"')
        faults["an output left out of ModelStructure"] = ("<Output ", "<Unknown ")
    else:
        faults["a derivative of nothing"] = ('derivative="%d"' % q.index, 'derivative="999"')
        faults["an output left out of ModelStructure"] = ("<Outputs>\n      <Unknown",
                                                          "<Outputs>\n      <Other")
    for fault, (old, new) in faults.items():
        planted = text.replace(old, new, 1)
        if planted == text:
            check(what + ": planted fault '%s' found its place" % fault, False)
            continue
        try:
            fmi_host.Description(planted.encode())
            check(what + ": the host rejects " + fault, False)
        except (fmi_host.DescriptionError, KeyError):
            check(what + ": the host rejects " + fault, True)


def derivative_checks(unit, what, start):
    """ME: d(derivatives)/d(states) by GetDirectionalDerivative against central
    differences of GetContinuousStateDerivatives, at the state after a short run."""
    d = unit.description
    inst = fmi_host.Instance(unit, cs=False)
    inst.initialize(start)
    x = inst.states()
    x = [v + 0.1 * (i % 3 - 1) for i, v in enumerate(x)]
    inst.derivatives(0.0, x)
    worst = 0.0
    for j in range(len(x)):
        seed = [1.0]
        exact = inst.directional_derivative(d.derivatives, [d.states[j]], seed)
        inst.derivatives(0.0, x)
        h = 1e-6 * (1 + abs(x[j]))
        xp, xm = list(x), list(x)
        xp[j] += h
        xm[j] -= h
        fp, fm = inst.derivatives(0.0, xp), inst.derivatives(0.0, xm)
        inst.derivatives(0.0, x)
        for i in range(len(x)):
            fd = (fp[i] - fm[i]) / (2 * h)
            worst = max(worst, abs(exact[i] - fd) / max(1.0, abs(fd)))
    check(what + ": directional derivatives equal central differences to 1e-6", worst < 1e-6,
          "(largest %.3g)" % worst)
    inst.close()


def state_checks(unit, what, start, h):
    """CS: get the state, step, restore, step again: the same values."""
    d = unit.description
    inst = fmi_host.Instance(unit, cs=True)
    inst.initialize(start)
    inst.do_step(0.0, h)
    saved = inst.get_state()
    inst.do_step(h, h)
    first = inst.get(d.states)
    inst.set_state(saved)
    inst.do_step(h, h)
    again = inst.get(d.states)
    inst.free_state(saved)
    inst.close()
    check(what + ": a restored state repeats the step exactly", first == again)


def case(name, model, sim_args, fmu_args, t_end, h, start_by_name, cs_tolerance=1e-9,
         method="RK4",
         me_tolerance=1e-6, extra=True, versions=("3", "2"), me=True):
    if WANTED and name not in WANTED:
        return
    csv_path = os.path.join(WORK, name + ".csv")
    run("sim", model, "--tmax", str(t_end), "--dt", str(h), "-o", csv_path, *sim_args)
    header, sim_rows = read_csv(csv_path)
    for version in versions:
        what = "%s FMI %s" % (name, version)
        fmu = os.path.join(WORK, "%s_fmi%s.fmu" % (name, version))
        run("fmu", model, "-o", fmu, "--fmi-version", version, "--step", str(h), *fmu_args)
        try:
            unit = fmi_host.Unit(fmu, os.path.join(WORK, "%s_fmi%s" % (name, version)))
        except fmi_host.DescriptionError as e:
            check(what + ": modelDescription.xml passes the structural checks", False, str(e))
            continue
        check(what + ": modelDescription.xml passes the structural checks", True)
        d = unit.description
        start = {d.by_name[n].vr: v for n, v in start_by_name.items()}
        structural(unit, what)
        if name == "double_pendulum":
            planted_errors(unit, what)
        record, rows = fmi_host.simulate_cs(unit, t_end, h, start)
        compare(what + " CS (%s, step %g)" % (method, h), unit, record, rows, header, sim_rows,
                cs_tolerance)
        if me:
            record, rows = fmi_host.simulate_me(unit, t_end, h, start)
            compare(what + " ME (host RK4, step %g)" % h, unit, record, rows, header, sim_rows,
                    me_tolerance)
        if extra:
            derivative_checks(unit, what, start)
            state_checks(unit, what, start, h)


os.makedirs(WORK, exist_ok=True)


def failures_checks():
    """Errors: an output over the model is a usage error and writes nothing; a
    model error is located; nothing half-written stays behind."""
    model = os.path.join(WORK, "copy.mbd")
    with open(os.path.join(SOURCE, "models/double_pendulum.mbd")) as f:
        text = f.read()
    with open(model, "w") as f:
        f.write(text)
    r = subprocess.run([YAMSC, "fmu", model, "-o", model], capture_output=True, text=True)
    with open(model) as f:
        check("-o naming the model: exit 2, the model untouched",
              r.returncode == 2 and f.read() == text, r.stderr[:200])
    broken = os.path.join(WORK, "broken.mbd")
    with open(broken, "w") as f:
        f.write("model broken\ndof q\nrigid b { mass = m }\n")
    out = os.path.join(WORK, "broken.fmu")
    r = subprocess.run([YAMSC, "fmu", broken, "-o", out], capture_output=True, text=True)
    check("a model error: exit 1, located, no unit written",
          r.returncode == 1 and (broken + ":3:") in r.stderr and not os.path.exists(out),
          r.stderr[:200])
    leftovers = [n for n in os.listdir(WORK) if ".tmp." in n]
    check("no temporary file left", not leftovers, str(leftovers))


if not WANTED or "errors" in WANTED:
    failures_checks()
case("double_pendulum", os.path.join(SOURCE, "models/double_pendulum.mbd"),
     ["--u", "tau=1,f=0.5"], [], 2.0, 1e-3, {"tau": 1.0, "f": 0.5})
# The unit's co-simulation step with ABM4 (--method abm4) equals sim --method abm4
# (at 20 ms, where ABM4 and RK4 differ by 3e-5, so the method must be the one chosen),
# and the unit starts from the parameters --set gives (sim --set, the same).
case("double_pendulum_abm4", os.path.join(SOURCE, "models/double_pendulum.mbd"),
     ["--u", "tau=1,f=0.5", "--method", "abm4", "--set", "k=50,m2=2"],
     ["--method", "abm4", "--set", "k=50,m2=2"], 2.0, 0.02,
     {"tau": 1.0, "f": 0.5}, method="ABM4", versions=("3",), extra=False, me=False)
case("ext_pendulum", os.path.join(SOURCE, "tests/external/models/ext_pendulum.mbd"),
     ["--u", "tau=2", "--external",
      os.path.join(SOURCE, "tests/external/models/pendulum_loads.c")],
     ["--external", os.path.join(SOURCE, "tests/external/models/pendulum_loads.c")],
     1.0, 1e-3, {"tau": 2.0}, extra=False)
# A closed loop (constraint rows): the unit runs the constrained view, as sim.
case("four_bar", os.path.join(SOURCE, "models/four_bar.mbd"), ["--u", "tau=1"], [], 1.0, 1e-3,
     {"tau": 1.0}, versions=("3",), extra=False)
# The quasi-steady rotor block (`load rotor_table`) closed by the unit from its
# resources/: the 2-DOF land turbine in 16 m/s, the wind the unit's input.
table = os.path.join(SOURCE, "models/data/Cp_Ct_Cq.NREL5MW.txt")
pitch = 11.5 * math.pi / 180
case("rotor_table", os.path.join(SOURCE, "models/nrel5mw_land_operating.mbd"),
     ["--aero", table, "--wind", "16", "--u", "pitch=%.17g,gen_torque=43094" % pitch],
     ["--aero", table], 2.0, 0.01, {"V_wind": 16.0, "pitch": pitch, "gen_torque": 43094.0},
     versions=("3",), extra=False)
if not WANTED or "turbine_16dof" in WANTED:
    deck = os.path.join(SOURCE,
                        "tests/data/reference/land_16dof_free_decay/NREL5MW_Onshore_FreeDecay.fst")
    model = os.path.join(WORK, "turbine_16dof.mbd")
    run("from-openfast", deck, "-o", model)
    # The FMI 2.0 unit reuses the 3.0 unit's binary from the cache (a minute's compile).
    case("turbine_16dof", model, [], [], 1.0, 0.01, {}, extra=False)
if not WANTED or "blade_elements" in WANTED:
    # AeroDyn's BEM on the flexible blades (`load blade_elements`): the 16-DOF
    # model of the operating deck with --aero its AeroDyn file, the blade and
    # airfoil files carried under resources/aerodyn/; the unsteady airfoils
    # (UA_Mod 3) are discrete states the unit advances after each step, as sim;
    # model exchange advances them at CompletedIntegratorStep (the host RK4 there).
    deck = os.path.join(SOURCE, "tests/data/reference/operating/deck")
    model = os.path.join(WORK, "operating_16dof.mbd")
    run("from-openfast", os.path.join(deck, "NREL-5MW.fst"), "-o", model)
    aerodyn = os.path.join(deck, "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat")
    # Eight steps of the deck's 6.25 ms: the test's time is the unit's compile.
    case("blade_elements", model, ["--aero", aerodyn, "--wind", "12"], ["--aero", aerodyn],
         0.05, 0.00625, {"V_wind": 12.0}, versions=("3",), extra=False)
    if os.path.exists(os.path.join(WORK, "blade_elements_fmi3.fmu")):
        unit = fmi_host.Unit(os.path.join(WORK, "blade_elements_fmi3.fmu"),
                             os.path.join(WORK, "blade_elements_state"))
        names = [n for n in os.listdir(os.path.join(unit.resources, "aerodyn"))]
        check("blade_elements: the AeroDyn, blade and airfoil files under resources/aerodyn/",
              "NRELOffshrBsline5MW_Onshore_AeroDyn15.dat" in names and "Airfoils" in names and
              len(os.listdir(os.path.join(unit.resources, "aerodyn", "Airfoils"))) >= 8,
              str(names))
        xml = open(os.path.join(unit.folder, "modelDescription.xml")).read()
        check("blade_elements: canGetAndSetFMUState false (the airfoils' discrete states)",
              xml.count('canGetAndSetFMUState="false"') == 2)
        inst = fmi_host.Instance(unit, cs=True)
        inst.initialize({unit.description.by_name["V_wind"].vr: 12.0})
        try:
            inst.get_state()
            refused = False
        except fmi_host.FmiError:
            refused = True
        check("blade_elements: GetFMUState refused", refused)
        inst.close()

if failures:
    print("%d check(s) failed" % len(failures))
    sys.exit(1)
print("all checks passed")
