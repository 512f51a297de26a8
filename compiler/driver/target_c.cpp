// --lang c: C99, names prefixed by one identifier, float or double.
#include "driver/targets.hpp"

namespace yamsc::driver {

const Target c_target{Language::c,
                      "c",
                      {"c", "h"},
                      /*nested_namespaces=*/false,
                      /*header=*/true,
                      /*single_precision=*/true,
                      /*prints_module=*/true,
                      [](const TargetInput& in) { return codegen::emit_c(*in.module, in.emit); }};

} // namespace yamsc::driver
