#pragma once
// The kernel names what a user can do about an error or a warning (sf::Remedy);
// this words it in the command language.
#include <string>

#include "sandflow/core/error.hpp"

namespace sf::tcl {

// `text` with the remedy's advice appended (unchanged for Remedy::none).
std::string withRemedy(const std::string& text, const Advice& advice);

}  // namespace sf::tcl
