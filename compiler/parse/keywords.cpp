#include "parse/keywords.hpp"

namespace yamsc::parse {

const std::vector<std::string>& statement_keywords() {
    static const std::vector<std::string> words{
        "model",    "param",     "input",   "dof",    "gravity", "rigid",
        "flexible", "joint",     "force",   "torque", "spring",  "genforce",
        "approx",   "linearize", "initial", "output", "point"};
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
        for (const char* w :
             {"beam", "symbolic", "modes", "mode", "at", "translate", "rotate", "free", "order",
              "deg", "tip", "node", "on", "in", "stiffness", "damping"}) {
            all.emplace_back(w);
        }
        return all;
    }();
    return words;
}

} // namespace yamsc::parse
