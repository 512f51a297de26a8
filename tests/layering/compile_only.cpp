// `yamsc MODEL -o OUT` built against the compile path alone (yamsc_driver and the
// stages before it): this program links no runtime library, so it does not link
// at all if the compile path ever calls into the runtime (integrators, SUNDIALS,
// the JIT). tests/layering/check_compile_path.cmake runs it and compares its
// output with yamsc's.
#include "driver/commands.hpp"

#include <iostream>

int main(int argc, char** argv) {
    if (argc != 3) {
        std::cerr << "usage: compile_only MODEL.mbd OUT.cpp\n";
        return 2;
    }
    yamsc::driver::CompileOptions o;
    o.model = argv[1];
    o.output = argv[2];
    try {
        return yamsc::driver::compile(o, std::cout, std::cerr);
    } catch (const std::exception& e) {
        std::cerr << "compile_only: " << e.what() << "\n";
        return 1;
    }
}
