// The style sheet and the script of `canopy report`'s page (report/html_report.hpp), inlined into
// every page: sortable tables, image viewers zoomed and panned together, and the page's own check
// (#selftest) that tests/report/ reads back from a headless Chromium.
#pragma once

#include <string_view>

namespace canopy {

std::string_view report_page_style();
std::string_view report_page_script();

}  // namespace canopy
