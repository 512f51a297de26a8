#pragma once
// Flexible bodies of the checked model: their SID from a file or from a beam
// description (inline or an ElastoDyn file), asked of the data stage through
// model::DataSource, reduced to the modes the model uses, and the mode -> DOF map.
#include "model/data_source.hpp"
#include "model/expr_check.hpp"

#include <functional>
#include <set>

namespace yamsc::model {

struct FlexibleInputs {
    const SymbolTable& names;
    const NameValues& param_values; // defaults, for beam dimensions
    DataSource& data;               // SID and beam files, beam preprocessing
    diag::Diagnostics& diags;
};

/// A checked `flexible` block and, for a beam block, the beam its SID was made
/// of: the checker cuts it at the sections outputs name; the model keeps only
/// the SIDs.
struct CheckedFlexible {
    Flexible flex;
    std::optional<beam::Beam> beam;
};

/// Checks a `flexible NAME { ... }` block; nullopt after reporting errors.
std::optional<CheckedFlexible> check_flexible(const ast::FlexibleBody& body, FlexibleInputs& in);

/// The SID restricted to the modes `keep` (indices into sid's modes, in the new order).
sid::Sid select_modes(const sid::Sid& sid, const std::vector<int>& keep);

/// Calls f(term, node id or -1, block) for every Taylor block of a SID, nodes first.
void for_each_block(const sid::Sid& s,
                    const std::function<void(const std::string&, int, const sid::Taylor&)>& f);

/// The parameters of a symbolic flexible body: one per non-zero SID entry (NaN in
/// the SID: no default).
struct ShapeParameter {
    std::string name;
    std::optional<double> value;
};
std::vector<ShapeParameter> shape_parameters(const std::string& body, const Flexible& flex);

/// A polynomial in z from a mode-shape expression: coefficient of z^p at index p.
std::optional<std::vector<double>> polynomial_in_z(const Expr& e, const NameValues& values,
                                                   std::string& why);

} // namespace yamsc::model
