#include "report/markdown_html.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cstdlib>
#include <vector>

namespace canopy {

namespace {

std::vector<std::string_view> split_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            if (start < text.size()) lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) s.remove_suffix(1);
    return s;
}

// **bold** and `code`, the rest escaped.
std::string inline_html(std::string_view text) {
    std::string out;
    bool bold = false;
    for (size_t i = 0; i < text.size(); ++i) {
        if (text[i] == '`') {
            const size_t end = text.find('`', i + 1);
            if (end != std::string_view::npos) {
                out += "<code>" + html_escape(text.substr(i + 1, end - i - 1)) + "</code>";
                i = end;
                continue;
            }
        }
        if (text.compare(i, 2, "**") == 0 && (bold || text.find("**", i + 2) != std::string_view::npos)) {
            out += bold ? "</strong>" : "<strong>";
            bold = !bold;
            ++i;
            continue;
        }
        out += html_escape(text.substr(i, 1));
    }
    if (bold) out += "</strong>";
    return out;
}

std::vector<std::string_view> table_cells(std::string_view line) {
    line = trim(line);
    if (!line.empty() && line.front() == '|') line.remove_prefix(1);
    if (!line.empty() && line.back() == '|') line.remove_suffix(1);
    std::vector<std::string_view> cells;
    size_t start = 0;
    for (size_t i = 0; i <= line.size(); ++i)
        if (i == line.size() || line[i] == '|') {
            cells.push_back(trim(line.substr(start, i - start)));
            start = i + 1;
        }
    return cells;
}

// The number a cell starts with, for sorting ("1.18 [1.17, 1.19]" -> 1.18, "**1.00**" -> 1.00).
std::string sort_value(std::string_view cell) {
    std::string digits;
    for (char c : cell)
        if (c != '*' && c != ' ') digits += c;
        else if (!digits.empty()) break;
    char* end = nullptr;
    const double value = std::strtod(digits.c_str(), &end);
    if (digits.empty() || end == digits.c_str()) return "";
    return fmt::format(" data-value=\"{}\"", value);
}

std::string table_html(const std::vector<std::string_view>& lines) {
    std::string out = "<div class=\"table-scroll\"><table class=\"sortable\">\n<thead><tr>";
    const std::vector<std::string_view> header = table_cells(lines[0]);
    for (std::string_view cell : header) out += "<th>" + inline_html(cell) + "</th>";
    out += "</tr></thead>\n<tbody>\n";
    std::vector<bool> right;
    for (std::string_view cell : table_cells(lines[1])) right.push_back(!cell.empty() && cell.back() == ':');
    for (size_t r = 2; r < lines.size(); ++r) {
        out += "<tr>";
        const std::vector<std::string_view> cells = table_cells(lines[r]);
        for (size_t c = 0; c < cells.size(); ++c)
            out += fmt::format("<td{}{}>{}</td>", c < right.size() && right[c] ? " class=\"num\"" : "",
                               sort_value(cells[c]), inline_html(cells[c]));
        out += "</tr>\n";
    }
    return out + "</tbody></table></div>\n";
}

bool is_table_separator(std::string_view line) {
    line = trim(line);
    return line.size() >= 3 && line.front() == '|' &&
           std::all_of(line.begin(), line.end(), [](char c) { return c == '|' || c == '-' || c == ':' || c == ' '; });
}

}  // namespace

std::string html_escape(std::string_view text) {
    std::string out;
    out.reserve(text.size());
    for (char c : text) switch (c) {
            case '&': out += "&amp;"; break;
            case '<': out += "&lt;"; break;
            case '>': out += "&gt;"; break;
            case '"': out += "&quot;"; break;
            default: out += c;
        }
    return out;
}

std::string markdown_to_html(std::string_view markdown, int heading_offset) {
    const std::vector<std::string_view> lines = split_lines(markdown);
    std::string out, paragraph;
    bool in_list = false;
    const auto flush = [&] {
        if (!paragraph.empty()) out += "<p>" + inline_html(paragraph) + "</p>\n";
        paragraph.clear();
        if (in_list) out += "</ul>\n";
        in_list = false;
    };
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string_view line = trim(lines[i]);
        if (line.empty()) {
            flush();
            continue;
        }
        if (line.front() == '#') {
            flush();
            const size_t level = line.find_first_not_of('#');
            if (level != std::string_view::npos && line[level] == ' ') {
                const int h = std::min(6, int(level) + heading_offset);
                out += fmt::format("<h{0}>{1}</h{0}>\n", h, inline_html(trim(line.substr(level))));
                continue;
            }
        }
        if (line.front() == '|' && i + 1 < lines.size() && is_table_separator(lines[i + 1])) {
            flush();
            std::vector<std::string_view> table{line, lines[i + 1]};
            i += 2;
            while (i < lines.size() && !trim(lines[i]).empty() && trim(lines[i]).front() == '|') table.push_back(lines[i++]);
            --i;
            out += table_html(table);
            continue;
        }
        if (line.size() > 2 && line[0] == '-' && line[1] == ' ') {
            if (!paragraph.empty()) {
                out += "<p>" + inline_html(paragraph) + "</p>\n";
                paragraph.clear();
            }
            if (!in_list) out += "<ul>\n";
            in_list = true;
            out += "<li>" + inline_html(line.substr(2)) + "</li>\n";
            continue;
        }
        if (in_list && (lines[i].front() == ' ' || lines[i].front() == '\t')) {  // a list item's continuation
            constexpr std::string_view kItemEnd = "</li>\n";  // the open item's end, which the text goes before
            out.insert(out.size() - kItemEnd.size(), " " + inline_html(line));
            continue;
        }
        if (in_list) flush();
        paragraph += paragraph.empty() ? std::string(line) : " " + std::string(line);
    }
    flush();
    return out;
}

}  // namespace canopy
