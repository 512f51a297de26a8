"""An FMI host of our own, written from the FMI 3.0 and 2.0 standards' text:
unzips a unit, reads and checks its modelDescription.xml against the
standard's structural rules, loads its binary and drives it as a tool would
(co-simulation with doStep, model exchange with a host-side RK4), with the
Python standard library only (ctypes, zipfile, xml.etree)."""

import ctypes as C
import os
import platform
import tempfile
import xml.etree.ElementTree as ET
import zipfile


class DescriptionError(Exception):
    pass


class Variable:
    def __init__(self, name, vr, kind, causality, variability, initial, start, derivative,
                 unit, index):
        self.name, self.vr, self.kind = name, vr, kind
        self.causality, self.variability, self.initial = causality, variability, initial
        self.start, self.derivative, self.unit, self.index = start, derivative, unit, index


class Description:
    """What a host needs of a modelDescription.xml, the same for 3.0 and 2.0:
    variables by value reference, the states in the order of their
    derivatives, the outputs, and the model structure's lists (by value reference)."""

    def __init__(self, text):
        root = ET.fromstring(text)
        if root.tag != "fmiModelDescription":
            raise DescriptionError("the root element is not fmiModelDescription")
        self.version = root.get("fmiVersion")
        if self.version not in ("3.0", "2.0"):
            raise DescriptionError("fmiVersion %r" % self.version)
        self.fmi3 = self.version == "3.0"
        self.model_name = root.get("modelName")
        self.token = root.get("instantiationToken" if self.fmi3 else "guid")
        me, cs = root.find("ModelExchange"), root.find("CoSimulation")
        if me is None or cs is None:
            raise DescriptionError("the unit lacks ModelExchange or CoSimulation")
        self.identifier = cs.get("modelIdentifier")
        if me.get("modelIdentifier") != self.identifier:
            raise DescriptionError("ModelExchange and CoSimulation name different binaries")
        self.me_attributes, self.cs_attributes = dict(me.attrib), dict(cs.attrib)
        self.units = {u.get("name") for u in root.iter("Unit")}
        self.variables = []
        if self.fmi3:
            for k, e in enumerate(root.find("ModelVariables")):
                self.variables.append(self._variable3(e, k + 1))
        else:
            for k, e in enumerate(root.find("ModelVariables").findall("ScalarVariable")):
                self.variables.append(self._variable2(e, k + 1))
        self.by_vr = {}
        self.by_name = {}
        self.by_index = {v.index: v for v in self.variables}
        for v in self.variables:
            if v.vr in self.by_vr:
                raise DescriptionError("value reference %d is given twice" % v.vr)
            if v.name in self.by_name:
                raise DescriptionError("the name %r is given twice" % v.name)
            self.by_vr[v.vr] = v
            self.by_name[v.name] = v
        self.structure = self._structure(root.find("ModelStructure"))
        self.check()
        # The continuous states, in the order of their derivatives (both standards).
        self.derivatives = [vr for vr, _ in self.structure["derivatives"]]
        self.states = [self.by_vr[vr].derivative for vr in self.derivatives]

    def _variable3(self, e, index):
        kind = e.tag
        der = e.get("derivative")
        start = e.get("start")
        return Variable(e.get("name"), int(e.get("valueReference")), kind,
                        e.get("causality", "local"), e.get("variability",
                        "continuous" if kind == "Float64" else "discrete"),
                        e.get("initial"), None if start is None else float(start),
                        None if der is None else int(der), e.get("unit"), index)

    def _variable2(self, e, index):
        typed = [c for c in e if c.tag in ("Real", "Integer", "Boolean", "String", "Enumeration")]
        if len(typed) != 1:
            raise DescriptionError("ScalarVariable %r has no single type element" % e.get("name"))
        t = typed[0]
        der = t.get("derivative")
        start = t.get("start")
        return Variable(e.get("name"), int(e.get("valueReference")),
                        "Float64" if t.tag == "Real" else "Int32", e.get("causality", "local"),
                        e.get("variability", "continuous" if t.tag == "Real" else "discrete"),
                        e.get("initial"), None if start is None else float(start),
                        None if der is None else int(der), t.get("unit"), index)

    def _structure(self, element):
        """Lists of (value reference, dependencies or None) per kind."""
        if element is None:
            raise DescriptionError("no ModelStructure")
        out = {"outputs": [], "derivatives": [], "initial_unknowns": []}
        if self.fmi3:
            tags = {"Output": "outputs", "ContinuousStateDerivative": "derivatives",
                    "InitialUnknown": "initial_unknowns"}
            for e in element:
                if e.tag not in tags:
                    continue
                deps = e.get("dependencies")
                out[tags[e.tag]].append((int(e.get("valueReference")),
                                         None if deps is None else [int(d) for d in deps.split()]))
        else:
            tags = {"Outputs": "outputs", "Derivatives": "derivatives",
                    "InitialUnknowns": "initial_unknowns"}
            for group in element:
                for e in group.findall("Unknown"):
                    index = int(e.get("index"))
                    if index not in self.by_index:
                        raise DescriptionError("ModelStructure names index %d, no variable" % index)
                    deps = e.get("dependencies")
                    for d in (deps or "").split():
                        if int(d) not in self.by_index:
                            raise DescriptionError("dependency index %s names no variable" % d)
                    out[tags[group.tag]].append(
                        (self.by_index[index].vr, None if deps is None else
                         [self.by_index[int(d)].vr for d in deps.split()]))
            # FMI 2.0: the derivative attribute is an index; the host works in value references.
            for v in self.variables:
                if v.derivative is not None:
                    if v.derivative not in self.by_index:
                        raise DescriptionError("%s: derivative index %d names no variable"
                                               % (v.name, v.derivative))
                    v.derivative = self.by_index[v.derivative].vr
            if [index for index, _ in out["initial_unknowns"]] != sorted(
                    index for index, _ in out["initial_unknowns"]):
                raise DescriptionError("InitialUnknowns are not sorted by index")
        return out

    # The standard's table of legal combinations of causality and variability,
    # and the initial values each allows (FMI 3.0 2.4.7.4, FMI 2.0 2.2.7).
    LEGAL = {
        ("parameter", "fixed"): {"exact"}, ("parameter", "tunable"): {"exact"},
        ("calculatedParameter", "fixed"): {"calculated", "approx"},
        ("calculatedParameter", "tunable"): {"calculated", "approx"},
        ("input", "discrete"): {None}, ("input", "continuous"): {None},
        ("output", "constant"): {"exact"}, ("output", "discrete"): {"calculated", "exact", "approx"},
        ("output", "continuous"): {"calculated", "exact", "approx"},
        ("local", "constant"): {"exact"}, ("local", "fixed"): {"calculated", "approx"},
        ("local", "tunable"): {"calculated", "approx"},
        ("local", "discrete"): {"calculated", "exact", "approx"},
        ("local", "continuous"): {"calculated", "exact", "approx"},
        ("independent", "continuous"): {None},
    }

    def check(self):
        independents = [v for v in self.variables if v.causality == "independent"]
        if len(independents) > 1 or (self.fmi3 and len(independents) != 1):
            raise DescriptionError("%d independent variables" % len(independents))
        for v in self.variables:
            key = (v.causality, v.variability)
            if key not in self.LEGAL:
                raise DescriptionError("%s: causality %s with variability %s is not allowed"
                                       % ((v.name,) + key))
            allowed = self.LEGAL[key]
            if v.initial not in allowed and not (v.initial is None and None not in allowed):
                raise DescriptionError("%s: initial=%s is not allowed for %s %s"
                                       % ((v.name, v.initial) + key))
            needs_start = v.initial in ("exact", "approx") or v.causality == "input" or (
                v.initial is None and None not in allowed and "exact" in allowed
                and len(allowed) == 1)
            if needs_start and v.start is None:
                raise DescriptionError("%s: no start value" % v.name)
            if v.start is not None and (v.initial == "calculated" or v.causality == "independent"):
                raise DescriptionError("%s: a start value where none is allowed" % v.name)
            if v.unit and v.unit not in self.units:
                raise DescriptionError("%s: unit %r is not defined" % (v.name, v.unit))
            if v.derivative is not None and self.fmi3:
                if v.derivative not in self.by_vr:
                    raise DescriptionError("%s: derivative of vr %d, no variable"
                                           % (v.name, v.derivative))
            if v.derivative is not None:
                of = self.by_vr[v.derivative]
                if of.kind != "Float64" or of.variability != "continuous":
                    raise DescriptionError("%s: derivative of %s, not a continuous real"
                                           % (v.name, of.name))
        outputs = [vr for vr, _ in self.structure["outputs"]]
        declared = [v.vr for v in self.variables if v.causality == "output"]
        if outputs != declared:
            raise DescriptionError("ModelStructure's outputs are not the outputs, in order")
        with_derivative = [v.vr for v in self.variables if v.derivative is not None]
        if sorted(vr for vr, _ in self.structure["derivatives"]) != sorted(with_derivative):
            raise DescriptionError("the state derivatives are not those with a derivative attribute")
        states = {self.by_vr[vr].derivative for vr in with_derivative}
        inputs = {v.vr for v in self.variables if v.causality == "input"}
        for kind in ("outputs", "derivatives"):
            for vr, deps in self.structure[kind]:
                if vr not in self.by_vr:
                    raise DescriptionError("ModelStructure names vr %d, no variable" % vr)
                for d in deps or []:
                    if d not in states and d not in inputs:
                        raise DescriptionError("%s depends on %s, not a state or an input"
                                               % (self.by_vr[vr].name, self.by_vr[d].name))
        must = {v.vr for v in self.variables if v.causality == "output"
                and v.initial in ("approx", "calculated")}
        must |= {vr for vr in with_derivative
                 if self.by_vr[vr].initial in ("approx", "calculated")}
        given = [vr for vr, _ in self.structure["initial_unknowns"]]
        if set(given) != must or len(given) != len(set(given)):
            raise DescriptionError("InitialUnknowns are not the outputs and derivatives calculated "
                                   "at initialization")
        knowns = states | inputs | {v.vr for v in self.variables if v.initial == "exact"}
        for vr, deps in self.structure["initial_unknowns"]:
            for d in deps or []:
                if d not in knowns:
                    raise DescriptionError("initial unknown %s depends on %s, not known at "
                                           "initialization" % (self.by_vr[vr].name,
                                                               self.by_vr[d].name))


LOG = C.CFUNCTYPE(None, C.c_void_p, C.c_int, C.c_char_p, C.c_char_p)
# fmi2CallbackLogger is variadic; the fixed arguments are read alike on x86-64.
LOG2 = C.CFUNCTYPE(None, C.c_void_p, C.c_char_p, C.c_int, C.c_char_p, C.c_char_p)
ALLOCATE = C.CFUNCTYPE(C.c_void_p, C.c_size_t, C.c_size_t)
FREE = C.CFUNCTYPE(None, C.c_void_p)
STEP_FINISHED = C.CFUNCTYPE(None, C.c_void_p, C.c_int)


class Callbacks2(C.Structure):
    _fields_ = [("logger", LOG2), ("allocateMemory", ALLOCATE), ("freeMemory", FREE),
                ("stepFinished", STEP_FINISHED), ("componentEnvironment", C.c_void_p)]


class EventInfo2(C.Structure):
    _fields_ = [("newDiscreteStatesNeeded", C.c_int), ("terminateSimulation", C.c_int),
                ("nominalsOfContinuousStatesChanged", C.c_int),
                ("valuesOfContinuousStatesChanged", C.c_int),
                ("nextEventTimeDefined", C.c_int), ("nextEventTime", C.c_double)]


class FmiError(Exception):
    pass


_libc = C.CDLL(None)
_libc.calloc.restype = C.c_void_p
_libc.calloc.argtypes = [C.c_size_t, C.c_size_t]
_libc.free.argtypes = [C.c_void_p]


class Unit:
    """A unit unzipped into a folder of its own, its binary loaded."""

    def __init__(self, fmu_path, folder=None):
        self.folder = folder or tempfile.mkdtemp(prefix="fmi_host_")
        with zipfile.ZipFile(fmu_path) as z:
            bad = z.testzip()
            if bad:
                raise FmiError("the archive's entry %s is damaged" % bad)
            z.extractall(self.folder)
        with open(os.path.join(self.folder, "modelDescription.xml"), "rb") as f:
            self.description = Description(f.read())
        d = self.description
        machine = platform.machine()
        sub = ("%s-linux" % machine) if d.fmi3 else "linux64"
        self.binary = os.path.join(self.folder, "binaries", sub, d.identifier + ".so")
        self.lib = C.CDLL(self.binary, mode=os.RTLD_LOCAL | os.RTLD_NOW)
        self.messages = []
        self._log = LOG(lambda env, status, category, message: self.messages.append(
            (status, (category or b"").decode(), (message or b"").decode())))
        self._log2 = LOG2(lambda env, name, status, category, message: self.messages.append(
            (status, (category or b"").decode(), (message or b"").decode())))
        self._callbacks2 = Callbacks2(self._log2, ALLOCATE(lambda n, s: _libc.calloc(n, s)),
                                      FREE(lambda p: _libc.free(p)), STEP_FINISHED(0), None)
        self.resources = os.path.join(self.folder, "resources") + os.sep

    def exported(self):
        """The dynamic symbols the binary exports (nm -D), or None without nm."""
        import subprocess
        try:
            text = subprocess.run(["nm", "-D", "--defined-only", self.binary], check=True,
                                  capture_output=True, text=True).stdout
        except (OSError, subprocess.CalledProcessError):
            return None
        return sorted(line.split()[-1] for line in text.splitlines()
                      if line.split()[1:2] and line.split()[1] in "TWDBRVu")

    def fn(self, name, restype, *argtypes):
        f = getattr(self.lib, name)
        f.restype = restype
        f.argtypes = list(argtypes)
        return f


def ok(status, what):
    if status not in (0, 1):  # OK, Warning
        raise FmiError("%s returned status %d" % (what, status))


class Instance:
    """One instance of a unit, FMI 3.0 or 2.0, co-simulation or model exchange."""

    def __init__(self, unit, cs, name="host"):
        self.unit, self.cs = unit, cs
        d = unit.description
        self.d = d
        P, I, D = C.c_void_p, C.c_int, C.c_double
        u = unit
        self.fmi3 = d.fmi3
        if d.fmi3:
            if cs:
                f = u.fn("fmi3InstantiateCoSimulation", P, C.c_char_p, C.c_char_p, C.c_char_p,
                         C.c_bool, C.c_bool, C.c_bool, C.c_bool, P, C.c_size_t, P, LOG, P)
                self.handle = f(name.encode(), d.token.encode(), u.resources.encode(), False,
                                True, False, False, None, 0, None, u._log, None)
            else:
                f = u.fn("fmi3InstantiateModelExchange", P, C.c_char_p, C.c_char_p, C.c_char_p,
                         C.c_bool, C.c_bool, P, LOG)
                self.handle = f(name.encode(), d.token.encode(), u.resources.encode(), False,
                                True, None, u._log)
        else:
            f = u.fn("fmi2Instantiate", P, C.c_char_p, I, C.c_char_p, C.c_char_p,
                     C.POINTER(Callbacks2), I, I)
            uri = "file://" + u.resources
            self.handle = f(name.encode(), 1 if cs else 0, d.token.encode(), uri.encode(),
                            C.byref(u._callbacks2), 0, 1)
        if not self.handle:
            raise FmiError("instantiation failed: %s" % u.messages)
        self.prefix = "fmi3" if d.fmi3 else "fmi2"

    def call(self, name, *args):
        f = getattr(self.unit.lib, self.prefix + name)
        f.restype = C.c_int
        ok(f(C.c_void_p(self.handle), *args), self.prefix + name)

    def set(self, values):
        """values: {vr: number}; reals and integers by the variables' kinds."""
        reals = [(vr, x) for vr, x in values.items() if self.d.by_vr[vr].kind == "Float64"]
        ints = [(vr, x) for vr, x in values.items() if self.d.by_vr[vr].kind != "Float64"]
        for items, ctype, name in ((reals, C.c_double, "Float64" if self.fmi3 else "Real"),
                                   (ints, C.c_int32, "Int32" if self.fmi3 else "Integer")):
            if not items:
                continue
            vrs = (C.c_uint32 * len(items))(*[vr for vr, _ in items])
            xs = (ctype * len(items))(*[x for _, x in items])
            if self.fmi3:
                self.call("Set" + name, vrs, C.c_size_t(len(items)), xs, C.c_size_t(len(items)))
            else:
                self.call("Set" + name, vrs, C.c_size_t(len(items)), xs)

    def get(self, vrs):
        a = (C.c_uint32 * len(vrs))(*vrs)
        out = (C.c_double * len(vrs))()
        if self.fmi3:
            self.call("GetFloat64", a, C.c_size_t(len(vrs)), out, C.c_size_t(len(vrs)))
        else:
            self.call("GetReal", a, C.c_size_t(len(vrs)), out)
        return list(out)

    def initialize(self, start_values=None):
        if self.fmi3:
            self.call("EnterInitializationMode", C.c_bool(False), C.c_double(0), C.c_double(0),
                      C.c_bool(False), C.c_double(0))
        else:
            self.call("SetupExperiment", C.c_int(0), C.c_double(0), C.c_double(0), C.c_int(0),
                      C.c_double(0))
            self.call("EnterInitializationMode")
        if start_values:
            self.set(start_values)
        self.call("ExitInitializationMode")
        if not self.cs:
            # Event mode after initialization: settle, then continuous time.
            if self.fmi3:
                flags = [C.c_bool() for _ in range(5)]
                t = C.c_double()
                self.call("UpdateDiscreteStates", *[C.byref(x) for x in flags], C.byref(t))
            else:
                info = EventInfo2()
                self.call("NewDiscreteStates", C.byref(info))
            self.call("EnterContinuousTimeMode")

    def do_step(self, t, h):
        if self.fmi3:
            flags = [C.c_bool() for _ in range(3)]
            last = C.c_double()
            self.call("DoStep", C.c_double(t), C.c_double(h), C.c_bool(True),
                      *[C.byref(x) for x in flags], C.byref(last))
        else:
            self.call("DoStep", C.c_double(t), C.c_double(h), C.c_int(1))

    def states(self):
        n = len(self.d.states)
        x = (C.c_double * n)()
        self.call("GetContinuousStates", x, C.c_size_t(n))
        return list(x)

    def derivatives(self, t, x):
        n = len(x)
        self.call("SetTime", C.c_double(t))
        self.call("SetContinuousStates", (C.c_double * n)(*x), C.c_size_t(n))
        dx = (C.c_double * n)()
        self.call("GetContinuousStateDerivatives" if self.fmi3 else "GetDerivatives", dx,
                  C.c_size_t(n))
        return list(dx)

    def completed_step(self):
        a, b = (C.c_bool(), C.c_bool()) if self.fmi3 else (C.c_int(), C.c_int())
        self.call("CompletedIntegratorStep", (C.c_bool if self.fmi3 else C.c_int)(1),
                  C.byref(a), C.byref(b))

    def directional_derivative(self, unknowns, knowns, seed):
        U = (C.c_uint32 * len(unknowns))(*unknowns)
        K = (C.c_uint32 * len(knowns))(*knowns)
        S = (C.c_double * len(seed))(*seed)
        out = (C.c_double * len(unknowns))()
        if self.fmi3:
            self.call("GetDirectionalDerivative", U, C.c_size_t(len(unknowns)), K,
                      C.c_size_t(len(knowns)), S, C.c_size_t(len(seed)), out,
                      C.c_size_t(len(unknowns)))
        else:
            self.call("GetDirectionalDerivative", U, C.c_size_t(len(unknowns)), K,
                      C.c_size_t(len(knowns)), S, out)
        return list(out)

    def get_state(self):
        s = C.c_void_p()
        self.call("GetFMUState" if self.fmi3 else "GetFMUstate", C.byref(s))
        return s

    def set_state(self, s):
        self.call("SetFMUState" if self.fmi3 else "SetFMUstate", s)

    def free_state(self, s):
        self.call("FreeFMUState" if self.fmi3 else "FreeFMUstate", C.byref(s))

    def close(self):
        self.call("Terminate")
        f = getattr(self.unit.lib, self.prefix + "FreeInstance")
        f.restype = None
        f(C.c_void_p(self.handle))
        self.handle = None


def recorded(d):
    """The value references a run records by default: the states and the outputs."""
    return [v.vr for v in d.variables if v.causality == "output" or v.vr in d.states]


def simulate_cs(unit, t_end, h, start_values=None, record=None):
    """Co-simulation: doStep by h to t_end; rows [t, values of `record`]."""
    record = record or recorded(unit.description)
    inst = Instance(unit, cs=True)
    inst.initialize(start_values)
    rows = [[0.0] + inst.get(record)]
    n = int(round(t_end / h))
    for k in range(n):
        inst.do_step(k * h, h)
        rows.append([(k + 1) * h] + inst.get(record))
    inst.close()
    return record, rows


def simulate_me(unit, t_end, h, start_values=None, record=None):
    """Model exchange with the host's classical RK4 at step h."""
    record = record or recorded(unit.description)
    inst = Instance(unit, cs=False)
    inst.initialize(start_values)
    x = inst.states()
    rows = [[0.0] + inst.get(record)]
    n = int(round(t_end / h))
    for k in range(n):
        t = k * h
        k1 = inst.derivatives(t, x)
        k2 = inst.derivatives(t + h / 2, [a + h / 2 * b for a, b in zip(x, k1)])
        k3 = inst.derivatives(t + h / 2, [a + h / 2 * b for a, b in zip(x, k2)])
        k4 = inst.derivatives(t + h, [a + h * b for a, b in zip(x, k3)])
        x = [a + h / 6 * (b1 + 2 * b2 + 2 * b3 + b4)
             for a, b1, b2, b3, b4 in zip(x, k1, k2, k3, k4)]
        inst.derivatives((k + 1) * h, x)
        inst.completed_step()
        # A unit may move the state at a completed step (a constrained model's
        # projection onto its constraints): continue from its state.
        x = inst.states()
        rows.append([(k + 1) * h] + inst.get(record))
    inst.close()
    return record, rows
