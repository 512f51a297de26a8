#pragma once
// Owning handles for the SUNDIALS objects one CVODE run needs. SUNDIALS 6 ties
// every object to a SUNContext, so the context is declared first and freed last.
#include <cvode/cvode.h>
#include <nvector/nvector_serial.h>
#include <sundials/sundials_context.h>
#include <sunlinsol/sunlinsol_dense.h>
#include <sunmatrix/sunmatrix_dense.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <type_traits>

namespace yamsc::runtime::sundials {

class Context {
public:
    Context() {
        if (SUNContext_Create(nullptr, &ctx_) != 0 || ctx_ == nullptr)
            throw std::runtime_error("cannot create a SUNDIALS context");
    }
    ~Context() { SUNContext_Free(&ctx_); }
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;
    operator SUNContext() const { return ctx_; }

private:
    SUNContext ctx_ = nullptr;
};

struct VectorDeleter {
    void operator()(N_Vector v) const { N_VDestroy(v); }
};
struct MatrixDeleter {
    void operator()(SUNMatrix m) const { SUNMatDestroy(m); }
};
struct LinearSolverDeleter {
    void operator()(SUNLinearSolver s) const { SUNLinSolFree(s); }
};
struct CvodeMemoryDeleter {
    void operator()(void* mem) const { CVodeFree(&mem); }
};

using Vector = std::unique_ptr<std::remove_pointer_t<N_Vector>, VectorDeleter>;
using Matrix = std::unique_ptr<std::remove_pointer_t<SUNMatrix>, MatrixDeleter>;
using LinearSolver = std::unique_ptr<std::remove_pointer_t<SUNLinearSolver>, LinearSolverDeleter>;
using CvodeMemory = std::unique_ptr<void, CvodeMemoryDeleter>;

/// SUNDIALS constructors return null when they run out of memory.
template <class Handle> Handle checked(Handle handle, const char* what) {
    if (!handle) throw std::runtime_error(std::string("SUNDIALS could not allocate ") + what);
    return handle;
}

} // namespace yamsc::runtime::sundials
