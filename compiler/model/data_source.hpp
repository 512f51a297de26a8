#pragma once
// What the checker asks of the data stage (compiler/data/): the SID of a
// flexible body, from a file or from a beam. The checker validates what the
// model wrote and asks through this interface; it never opens a file or runs
// the beam preprocessor. data::FileSource reads files and integrates shapes;
// stage tests give the checker a fake.
#include "beam/beam.hpp"
#include "diag/diagnostics.hpp"
#include "sid/sid.hpp"

#include <optional>
#include <string>
#include <vector>

namespace yamsc::model {

class DataSource {
public:
    virtual ~DataSource() = default;

    /// The SID in the file `name` (relative names start at the model's folder).
    /// nullopt after reporting located errors (the file's, or one at `at`).
    virtual std::optional<sid::Sid> sid_file(const std::string& name, const diag::Location& at,
                                             diag::Diagnostics& diags) = 0;

    /// The beam in a beam file of `format` (elastodyn_tower, elastodyn_blade) with
    /// the named modes, `length` long. nullopt after reporting errors.
    virtual std::optional<beam::Beam> beam_file(const std::string& format, const std::string& name,
                                                double length,
                                                const std::vector<std::string>& modes,
                                                const diag::Location& at,
                                                diag::Diagnostics& diags) = 0;

    /// The SID of a beam: its shape integrals, geometric stiffness and nodes
    /// (Appendix B/C) for flexible body `body`. nullopt after reporting at `at` why
    /// the beam is not valid.
    virtual std::optional<sid::Sid> beam_sid(const beam::Beam& beam, const std::string& body,
                                             const diag::Location& at,
                                             diag::Diagnostics& diags) = 0;

    /// The inertia integrals of the part of a (valid) beam beyond its SID node
    /// `node` (0-based), for the loads through that section. nullopt after
    /// reporting at `at` (the default: this source cannot cut beams).
    virtual std::optional<sid::Sid> section_sid(const beam::Beam& beam, int node,
                                                const diag::Location& at,
                                                diag::Diagnostics& diags) {
        (void)beam;
        (void)node;
        diags.error(diag::Kind::NotSupported, at, "this data source cannot cut beams");
        return std::nullopt;
    }
};

} // namespace yamsc::model
