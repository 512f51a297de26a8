// with_external_channels: an external function as the derivation sees it. Its
// results become input channels the generated code fills by calling the
// function, its arguments outputs the generated code evaluates first
// (docs/architecture.md), so Kane's method, the Jacobians and the outputs'
// machinery need nothing new.
#include "model/model.hpp"

namespace yamsc::model {
Model with_external_channels(const Model& model) {
    Model m = model;
    for (const External& e : model.externals) {
        std::vector<Expr> results;
        for (int r = 0; r < e.results(); ++r) {
            Input in;
            in.name = e.name + "[" + std::to_string(r) + "]"; // not an identifier: no clash
            in.doc = "result " + std::to_string(r) + " of external function " + e.name;
            in.loc = e.loc;
            m.inputs.push_back(in);
            results.push_back(Expr{Expr::Kind::name, e.loc, in.name, 0, {}});
        }
        switch (e.kind) {
        case External::Kind::force:
            m.forces.push_back(
                Force{e.body, e.at, e.frame, {results[0], results[1], results[2]}, e.loc});
            break;
        case External::Kind::torque:
            m.torques.push_back(
                Torque{e.body, e.frame, {results[0], results[1], results[2]}, e.loc});
            break;
        case External::Kind::genforce:
            for (std::size_t i = 0; i < e.dofs.size(); ++i)
                m.genforces.push_back(GenForce{e.dofs[i], results[i], e.loc});
            break;
        }
        for (std::size_t i = 0; i < e.args.size(); ++i) {
            Output y;
            y.name = e.name + "(" + std::to_string(i) + ")";
            y.doc = "argument " + std::to_string(i) + " of external function " + e.name;
            y.value = e.args[i];
            y.frame = e.arg_frames[i];
            y.loc = e.loc;
            m.outputs.push_back(y);
        }
    }
    return m;
}

} // namespace yamsc::model
