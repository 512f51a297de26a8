// ns per call of a compiled model's rhs, outputs and outputs_from_qdd (what
// `yamsc sim` calls per stored row of a fixed-step run, with the q'' of the
// integrator's rhs; 0 when the library has none), through the C ABI that
// `yamsc sim` loads (runtime/include/yamsc/abi_export.hpp): the library of the
// JIT cache, as sim runs it. Compiled and run by bench/sim_speed.py:
//
//   jit_call_cost LIBRARY.so
//
// One fixed state (small deflections, the rotor turning), inputs 0, the
// model's default parameters; best of 7 batches.
#include <dlfcn.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using rhs_fn = void (*)(double, const double*, const double*, const double*, double*);
using outputs_fn = void (*)(double, const double*, const double*, const double*, const double*,
                            double*);
using outputs_from_qdd_fn = void (*)(double, const double*, const double*, const double*,
                                     const double*, const double*, double*);
using outputs_from_qdd_bound_fn = void (*)(double, const double*, const double*, const double*,
                                           const double*, const void*, double*);
using outputs_from_qdd_routines_fn = void (*)(outputs_from_qdd_fn*, outputs_from_qdd_bound_fn*);
using sizes_fn = void (*)(int*, int*, int*, int*);
using params_fn = void (*)(double*);

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: jit_call_cost LIBRARY.so\n");
        return 2;
    }
    void* h = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!h) {
        std::fprintf(stderr, "%s\n", dlerror());
        return 1;
    }
    const auto rhs = reinterpret_cast<rhs_fn>(dlsym(h, "yamsc_rhs"));
    const auto outputs = reinterpret_cast<outputs_fn>(dlsym(h, "yamsc_outputs"));
    const auto sizes = reinterpret_cast<sizes_fn>(dlsym(h, "yamsc_sizes"));
    const auto defaults = reinterpret_cast<params_fn>(dlsym(h, "yamsc_default_params"));
    const auto routines =
        reinterpret_cast<outputs_from_qdd_routines_fn>(dlsym(h, "yamsc_outputs_from_qdd_routines"));
    outputs_from_qdd_fn outputs_from_qdd = nullptr;
    outputs_from_qdd_bound_fn unused = nullptr;
    if (routines) routines(&outputs_from_qdd, &unused);
    if (!rhs || !sizes || !defaults) {
        std::fprintf(stderr, "%s is not a yamsc model\n", argv[1]);
        return 1;
    }
    int nq = 0, nu = 0, np = 0, ny = 0;
    sizes(&nq, &nu, &np, &ny);
    std::vector<double> p(np + 1), x(2 * nq), u(nu + 1, 0.0), xdot(2 * nq), y(ny + 1);
    defaults(p.data());
    for (int i = 0; i < 2 * nq; ++i) x[i] = 0.01 * ((i * 7) % 5 - 2) + (i == nq + 5 ? 1.27 : 0.0);
    double sink = 0.0, best_rhs = 1e30, best_outputs = 1e30, best_from_qdd = 1e30;
    using clock = std::chrono::steady_clock;
    for (int batch = 0; batch < 7; ++batch) {
        const auto t0 = clock::now();
        for (int i = 0; i < 20000; ++i) {
            rhs(0.1, x.data(), u.data(), p.data(), xdot.data());
            sink += xdot[2 * nq - 1];
        }
        const auto t1 = clock::now();
        for (int i = 0; outputs && i < 5000; ++i) {
            outputs(0.1, x.data(), x.data() + nq, u.data(), p.data(), y.data());
            sink += y[0];
        }
        const auto t2 = clock::now();
        for (int i = 0; outputs_from_qdd && i < 5000; ++i) {
            outputs_from_qdd(0.1, x.data(), x.data() + nq, xdot.data() + nq, u.data(), p.data(),
                             y.data());
            sink += y[0];
        }
        const auto t3 = clock::now();
        best_rhs = std::min(best_rhs, std::chrono::duration<double>(t1 - t0).count() / 20000);
        best_outputs =
            std::min(best_outputs, std::chrono::duration<double>(t2 - t1).count() / 5000);
        best_from_qdd =
            std::min(best_from_qdd, std::chrono::duration<double>(t3 - t2).count() / 5000);
    }
    std::printf("{\"rhs_ns\": %.1f, \"outputs_ns\": %.1f, \"outputs_from_qdd_ns\": %.1f, "
                "\"sink\": %g}\n",
                best_rhs * 1e9, outputs ? best_outputs * 1e9 : 0.0,
                outputs_from_qdd ? best_from_qdd * 1e9 : 0.0, sink);
    return 0;
}
