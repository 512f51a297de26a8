#include "ast/keywords.hpp"

namespace yamsc::ast {

const std::vector<std::string>& statement_keywords() {
    static const std::vector<std::string> words{
        "model",   "param",  "input",  "dof",      "gravity",  "rigid",     "flexible",
        "joint",   "force",  "torque", "spring",   "genforce", "approx",    "linearize",
        "initial", "output", "point",  "external", "load",     "constraint"};
    return words;
}

const std::vector<std::string>& flexible_item_keywords() {
    static const std::vector<std::string> words{"beam", "symbolic", "modes"};
    return words;
}

const std::vector<std::string>& beam_item_keywords() {
    static const std::vector<std::string> words{"mode", "modes"};
    return words;
}

const std::vector<std::string>& joint_step_keywords() {
    static const std::vector<std::string> words{"at", "translate", "rotate", "free"};
    return words;
}

const std::vector<std::string>& language_keywords() {
    static const std::vector<std::string> words = [] {
        std::vector<std::string> all = statement_keywords();
        for (const char* w : {"beam", "symbolic", "mode", "at", "translate", "rotate", "free",
                              "order", "deg", "on", "in", "stiffness", "damping"}) {
            all.emplace_back(w);
        }
        return all;
    }();
    return words;
}

const std::vector<std::string>& predefined_names() {
    static const std::vector<std::string> words{
        "ground",         "t", "pi", "position", "velocity", "angular_velocity", "reaction_force",
        "reaction_moment"};
    return words;
}

} // namespace yamsc::ast
