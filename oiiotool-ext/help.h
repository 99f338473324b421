// help.h: --help and --help-markdown (docs/mcdtool.md), both generated
// from the command, option and role tables.
#pragma once

#include <string>

namespace mcdtool {

/// The terminal help: usage, commands, guide roles, options, examples.
std::string help_text();

/// The reference page docs/mcdtool.md, as Markdown.
std::string help_markdown();

/// "mcdtool 0.1.0 (OpenImageIO 2.4.7)".
std::string version_text();

}  // namespace mcdtool
