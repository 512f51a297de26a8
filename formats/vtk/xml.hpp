#pragma once
// The XML that VTK's files use, and no more: a declaration, comments, elements
// with quoted attributes, text. No DOCTYPE, CDATA or entities other than XML's
// five. Every element and text keeps its byte offset, for located errors.
#include <cstddef>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace yamsc::vtk::xml {

struct Element {
    std::string name;
    std::vector<std::pair<std::string, std::string>> attributes;
    std::string text; // the text directly inside, concatenated
    std::size_t offset = 0, text_offset = 0;
    std::vector<Element> children;

    /// The attribute's value, or nullptr.
    const std::string* attribute(const std::string& key) const;
};

/// Where an offset is in a text: "name:line:col".
std::string where(const std::string& text, const std::string& name, std::size_t offset);

/// The root element. Throws diag::UserError("name:line:col: message").
Element parse(const std::string& text, const std::string& name, std::size_t max_depth);

} // namespace yamsc::vtk::xml
