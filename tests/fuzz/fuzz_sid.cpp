// libFuzzer target: a SID file through the reader. Properties: no crash, no
// sanitizer report, no exception; a rejected file reports an error; an accepted
// one survives the writer and reads back equal (sid/writer.hpp promises
// read_sid(write_sid(sid)) == sid).
#include "diag/diagnostics.hpp"
#include "sid/reader.hpp"
#include "sid/writer.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace yamsc;
    auto file = std::make_shared<const diag::SourceFile>(
        "fuzz.sid", std::string(reinterpret_cast<const char*>(data), size));
    diag::Diagnostics diags;
    auto sid = sid::read_sid(file, diags);
    (void)diags.render();
    if (!sid) {
        if (!diags.has_errors()) std::abort();
        return 0;
    }
    if (diags.has_errors()) std::abort(); // a result despite an error
    auto again = std::make_shared<const diag::SourceFile>("again.sid", sid::write_sid(*sid));
    diag::Diagnostics diags_again;
    auto reread = sid::read_sid(again, diags_again);
    if (!reread || !(*reread == *sid)) std::abort();
    return 0;
}
