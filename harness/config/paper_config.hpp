// Reads an experiment's [paper] table (config/paper_comparison.hpp).
#pragma once

#include "config/paper_comparison.hpp"
#include "config/toml_reader.hpp"
#include "core/registry.hpp"

namespace canopy {

// Schema (every error names file:line):
//   [paper]
//   id = "G-T7.1"  title = "..."  source = "Gumbau 2011, Table 7.1, L1928-1935"
//   unit = "fps" | "ms"           column_key = "screen" | "scene" | <parameter name>
//   columns = ["512", "1024"]     baseline = "Chebyshev"   notes = "..."
//   [[paper.row]]   label, technique, params = {...}, values = [481, 342]   (nan allowed: no number)
//   [[paper.claim]] text, left, right, metric = "time", relation = "less" | "greater" | "about",
//                   tolerance = 0.15, column = "" (all columns)
PaperComparison read_paper(TomlReader& section, const TechniqueRegistry& registry);

}  // namespace canopy
