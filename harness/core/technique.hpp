// The technique plug-in contract. A technique registers by name, declares typed parameters,
// and, for chosen parameter values, declares its FrameGraph: the resources and passes it needs
// (graph/frame_graph.hpp). The harness builds only what the graph declares.
#pragma once

#include "core/error_columns.hpp"
#include "core/param.hpp"
#include "core/param_block.hpp"
#include "graph/frame_graph.hpp"

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <optional>
#include <span>
#include <string>
#include <type_traits>
#include <vector>

namespace canopy {

// A combination of parameter values, each valid on its own, that a technique refuses because it
// would render something meaningless (e.g. a stored exponential that overflows its format).
struct ParamConflict {
    std::vector<std::string> params;  // the parameters involved, the one to change first
    std::string message;              // what would go wrong
    std::string hint;                 // the safe range, what to change
};

class Technique {
public:
    virtual ~Technique() = default;
    virtual std::string name() const = 0;         // "shadow.pcf"
    virtual std::string summary() const = 0;      // one line for `canopy list`
    virtual std::string paper() const = 0;        // where it comes from
    virtual std::vector<ParamSpec> params() const = 0;
    virtual FrameGraph graph(const ParamSet& params) const = 0;
    // Which error columns mean something for this technique: its family's declaration
    // (core/error_columns.hpp); reports show the others as "n/a".
    virtual ErrorColumns error_columns() const = 0;
    // The error metrics (results.json names, `canopy metrics`) its family's Pareto fronts are drawn
    // on by default (report/pareto.hpp): the errors that measure what the family changes. Every one
    // must belong to a group error_columns() declares. Default: FLIP, which every technique has.
    virtual std::vector<std::string> pareto_errors() const;
    // A refused combination of `params`, or nullopt. Checked by resolve_params when a config's
    // cases are expanded, before anything runs or is written.
    virtual std::optional<ParamConflict> conflict(const ParamSet& params) const;
};

// ParamSet::resolve with `technique`'s specs (`specs`: technique.params(), built once by a caller
// resolving many cases), then its conflict check: a refused combination throws ConfigError at the
// line of the first conflicting parameter the config gives (else at `where`), with the
// technique's hint.
ParamSet resolve_params(const Technique& technique, const std::vector<ParamSpec>& specs,
                        const std::map<std::string, ParamValue>& given, const std::map<std::string, int>& given_lines,
                        const SourceLocation& where);

}  // namespace canopy
