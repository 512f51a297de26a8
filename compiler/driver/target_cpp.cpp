// --lang cpp: C++17, header-only-friendly, the default target.
#include "driver/targets.hpp"

namespace yamsc::driver {

const Target cpp_target{
    Language::cpp,
    "cpp",
    {"cpp", "cc", "cxx", "hpp"},
    /*nested_namespaces=*/true,
    /*header=*/true,
    /*single_precision=*/false,
    /*prints_module=*/true,
    [](const TargetInput& in) { return codegen::emit_cpp(*in.module, in.emit); }};

} // namespace yamsc::driver
