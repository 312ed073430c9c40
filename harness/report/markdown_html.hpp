// The Markdown canopy's own reports write (paper.md, pareto.md: headings, paragraphs, lists,
// pipe tables, **bold**, `code`), as HTML for `canopy report`. Not a general Markdown parser:
// anything else is shown as escaped text.
#pragma once

#include <string>
#include <string_view>

namespace canopy {

// `text` with & < > " escaped.
std::string html_escape(std::string_view text);

// Headings shift down by `heading_offset` levels (a report's section is <h2>: paper.md's # becomes
// <h3>). Tables get class="sortable" and numeric cells a data-value for sorting.
std::string markdown_to_html(std::string_view markdown, int heading_offset = 2);

}  // namespace canopy
