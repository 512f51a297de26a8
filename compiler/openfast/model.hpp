#pragma once
// The `.mbd` text of an ElastoDyn turbine (docs/openfast.md): a template model whose
// bodies, joints and DOFs follow ElastoDyn's flags and whose loads are inputs.
#include "openfast/blade_deflection.hpp"
#include "openfast/deck.hpp"
#include "openfast/operation.hpp"
#include "openfast/rotor.hpp"

#include <map>
#include <optional>
#include <string>

namespace yamsc::openfast {

struct OpenFastModelInput {
    const openfast::OpenFastDeck* deck = nullptr;
    std::map<std::string, bool> dofs; ///< ElastoDyn flag -> on, after --dofs
    std::string name;                 ///< the model's name
    std::string source;               ///< how the deck was given, for the header comment
    std::string tower_path;           ///< the tower file as the model names it
    std::vector<std::string> blade_paths;
    std::optional<RigidProperties> rotor; ///< the blades rigid, some DOF on: one lumped rotor
    std::vector<RigidProperties> blades;  ///< every DOF off: each blade (rigid_blade())
    std::optional<RigidProperties> tower; ///< when the tower is rigid
    /// Tip values of the blades' twisted shapes (flexible blades): ElastoDyn's mapping
    /// of OoPDefl and IPDefl onto the blade DOFs.
    std::vector<BladeTipShapes> blade_tips;
    /// A full deck's wind, rotor block and controller (paths as the model names them).
    std::optional<Operation> operation;
    /// ServoDyn's yaw spring and damper on the yaw DOF (YawDOF on, ServoDyn on).
    std::optional<YawSpring> yaw_spring;
    std::string output_file; ///< the model's file name, for the command in its header
};

/// The model text. Warnings about approximated initial conditions go to `diags`.
std::string openfast_model_text(const OpenFastModelInput& in, diag::Diagnostics& diags);

/// `v` in the fewest digits that read back exactly, in the model language's syntax.
std::string mbd_number(double v);

/// A string literal of the model language.
std::string mbd_string(const std::string& text);

} // namespace yamsc::openfast
