#include "report/html_report.hpp"

#include "metrics/reference_degeneracy.hpp"

#include "core/registry.hpp"
#include "metrics/colormaps.hpp"
#include "metrics/metric_registry.hpp"
#include "report/atomic_file.hpp"
#include "report/json_record_reader.hpp"
#include "report/markdown_html.hpp"
#include "report/pareto.hpp"
#include "report/pareto_chart.hpp"
#include "report/report_page_assets.hpp"
#include "report/text_table.hpp"
#include "run/case_labels.hpp"

#include <fmt/format.h>

#include <cmath>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace canopy {

namespace fs = std::filesystem;

namespace {

std::string read_bytes(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::ostringstream bytes;
    bytes << in.rdbuf();
    return bytes.str();
}

std::string base64(std::string_view bytes) {
    static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (size_t i = 0; i < bytes.size(); i += 3) {
        const uint32_t b0 = uint8_t(bytes[i]), b1 = i + 1 < bytes.size() ? uint8_t(bytes[i + 1]) : 0,
                       b2 = i + 2 < bytes.size() ? uint8_t(bytes[i + 2]) : 0;
        const uint32_t n = (b0 << 16) | (b1 << 8) | b2;
        out += kDigits[(n >> 18) & 63];
        out += kDigits[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? kDigits[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? kDigits[n & 63] : '=';
    }
    return out;
}

// A PNG's width from its header (IHDR follows the 8-byte signature); 0 when not a PNG.
int png_width(std::string_view bytes) {
    if (bytes.size() < 24 || bytes.substr(1, 3) != "PNG") return 0;
    return (uint8_t(bytes[16]) << 24) | (uint8_t(bytes[17]) << 16) | (uint8_t(bytes[18]) << 8) | uint8_t(bytes[19]);
}

// The page's images, each read once: embedded ones are written once into <script type="text/plain">
// blocks that the panels' <img data-image> point at (a reference is shown beside every case).
class ImageStore {
public:
    ImageStore(const fs::path& run_dir, bool embed) : run_dir_(run_dir), embed_(embed) {}

    struct Entry {
        std::string id;      // the data block's id, or "" when linked
        std::string href;    // the relative path, when linked
        int width = 0;       // pixels (0: unknown)
        bool found = false;
    };

    const Entry& get(const std::string& relative) {
        auto it = entries_.find(relative);
        if (it != entries_.end()) return it->second;
        Entry entry;
        const fs::path file = run_dir_ / relative;
        std::error_code error;
        if (!relative.empty() && fs::is_regular_file(file, error)) {
            const std::string bytes = read_bytes(file);
            entry.found = true;
            entry.width = png_width(bytes);
            if (embed_) {
                entry.id = fmt::format("image-{}", entries_.size());
                blocks_ += fmt::format("<script type=\"text/plain\" id=\"{}\">data:image/png;base64,{}</script>\n", entry.id,
                                       base64(bytes));
            } else {
                entry.href = relative;
            }
        }
        return entries_.emplace(relative, entry).first->second;
    }

    // <img> for `relative`, its width a share of the panel so that `image_width` pixels fill it (a
    // heat map's colour bar lies beyond, seen when panned).
    std::string img(const std::string& relative, const std::string& alt, int image_width) {
        const Entry& e = get(relative);
        if (!e.found) return "";
        const double share = e.width > 0 && image_width > 0 ? 100.0 * e.width / image_width : 100.0;
        const std::string style = fmt::format(" style=\"width: {:.3f}%\"", share);
        if (embed_) return fmt::format("<img alt=\"{}\" data-image=\"{}\"{}>", html_escape(alt), e.id, style);
        return fmt::format("<img alt=\"{}\" src=\"{}\"{}>", html_escape(alt), html_escape(e.href), style);
    }

    const std::string& blocks() const { return blocks_; }

private:
    fs::path run_dir_;
    bool embed_;
    std::map<std::string, Entry> entries_;
    std::string blocks_;
};

std::string cell(const std::string& text, bool number = false, double value = NAN) {
    if (!number) return "<td>" + html_escape(text) + "</td>";
    return std::isfinite(value) ? fmt::format("<td class=\"num\" data-value=\"{}\">{}</td>", value, html_escape(text))
                                : "<td class=\"num\">" + html_escape(text) + "</td>";
}

std::string environment_section(const RunRecord& run) {
    const Environment& e = run.environment;
    std::vector<std::pair<std::string, std::string>> rows = {
        {"experiment", run.experiment},
        {"config", fmt::format("{} (hash {})", run.config_file, e.config_hash)},
        {"status", run.status + (run.error.empty() ? "" : ": " + run.error)},
        {"started / finished", fmt::format("{} / {}", run.started_at, run.finished_at)},
        {"device", fmt::format("{} ({}, {}), Vulkan {}", e.device.name, e.device.type, e.device.driver_info, e.device.api_version)},
        {"CPU", fmt::format("{}, {} threads allowed ({}), LP_NUM_THREADS {}", e.cpu_model, e.nproc, e.cpus_allowed, e.lp_num_threads)},
        {"load average", fmt::format("{:.2f} {:.2f} {:.2f}", e.load_average[0], e.load_average[1], e.load_average[2])},
        {"canopy", fmt::format("{} ({}), commit {}", e.canopy_version, e.build_type, commit_text(e))},
        {"measurement", fmt::format("{} warm-up frames, {} rounds of {} frames per case{}", run.warmup_frames, run.rounds,
                                    run.frames_per_sample, run.quick ? " (--quick: a smoke test, not a measurement)" : "")},
    };
    std::string html = "<h2 id=\"environment\">Environment</h2>\n";
    if (!e.binary_older_than.empty())
        html += fmt::format("<p class=\"warning\">The canopy binary was older than {}: these numbers may come from other "
                            "code than the commit says.</p>\n",
                            html_escape(e.binary_older_than));
    if (e.commit_mismatch())
        html += fmt::format("<p class=\"warning\">The canopy binary was built from {}, not from the checkout's commit "
                            "{}: these numbers come from the binary's code.</p>\n",
                            html_escape(e.binary_commit), html_escape(e.git_commit));
    html += "<div class=\"table-scroll\"><table class=\"environment\">\n";
    for (const auto& [key, value] : rows) html += "<tr>" + cell(key) + cell(value) + "</tr>\n";
    return html + "</table></div>\n";
}

std::string results_section(const RunRecord& run, const CaseLabels& labels) {
    const std::vector<const MetricInfo*> metrics = shown_metrics(run, shown_in_markdown);
    std::string html =
        "<h2 id=\"results\">Results</h2>\n<p class=\"hint\">Click a column's header to sort. Time: GPU time of the frame "
        "(median ± MAD over the rounds); ratio: to the group's baseline, paired round by round, with its 95 % "
        "interval.</p>\n<div class=\"table-scroll\"><table class=\"sortable\" id=\"results-table\">\n<thead><tr><th>group</th><th>technique</th><th>parameters</th>"
        "<th>GPU ms</th><th>time ratio</th>";
    for (const MetricInfo* m : metrics) html += "<th>" + html_escape(m->column) + "</th>";
    html += "<th>memory MiB</th><th>status</th></tr></thead>\n<tbody>\n";
    for (const CaseResult& c : run.cases) {
        const std::string group = c.group < run.groups.size() ? run.groups[c.group].name : "";
        html += "<tr>" + cell(group) + cell(c.technique) + cell(labels.parameters(c));
        const SampleStats& s = c.gpu_frame.stats;
        html += s.count ? cell(fmt::format("{:.3f} ± {:.3f}", s.median, s.mad), true, s.median) : cell("-", true);
        const Estimate ratio = c.group_baseline ? Estimate{1.0, {1.0, 1.0}, 0} : c.ratio.estimate;
        const bool has_ratio = c.group_baseline || c.ratio.measured();
        html += has_ratio ? cell(ratio_cell(ratio), true, ratio.value) : cell("-", true);
        for (const MetricInfo* m : metrics) {
            if (!c.image_error) {
                html += cell("-", true);
                continue;
            }
            const double value = m->meaningful_value(*c.image_error);
            html += cell(table_cell(*m, *c.image_error), true, m->percent ? 100 * value : value);
        }
        const double mib = double(c.memory.technique_bytes) / (1024.0 * 1024.0);
        html += cell(fmt::format("{:.2f}", mib), true, mib);
        // A case measured against a degenerate reference says so where its status is read.
        const std::string flag = degenerate_reference_text(degenerate_reasons(run, c));
        html += cell(c.ok ? (flag.empty() ? "ok" : "ok; " + flag) : "failed: " + c.error) + "</tr>\n";
    }
    return html + "</tbody></table></div>\n";
}

std::string pareto_section(const RunRecord& run, const CaseLabels& labels, const std::vector<std::string>& wanted) {
    const auto label = [&](const CaseResult& c) { return labels.label(c); };
    std::string html;
    for (const std::string& name : wanted.empty() ? default_pareto_metrics(run) : wanted) {
        const MetricInfo* metric = find_metric(name);
        if (!metric) continue;
        for (const ParetoFront& front : pareto_fronts(run, name)) {
            if (front.points.size() < 2) continue;
            html += fmt::format("<div class=\"chart\"><h3>{} — {}</h3>\n{}", html_escape(front.group),
                                html_escape(metric->title), pareto_svg(front, *metric, label));
            html += "<div class=\"table-scroll\"><table class=\"sortable\"><thead><tr><th>#</th><th>on the front</th><th>technique</th><th>parameters</th>"
                    "<th>time ratio</th><th>" +
                    html_escape(metric->column) + "</th><th>dominated by</th></tr></thead><tbody>\n";
            for (size_t i = 0; i < front.points.size(); ++i) {
                const ParetoPoint& p = front.points[i];
                std::string by;
                for (const ParetoPoint& q : front.points)
                    if (p.dominated && q.result->id == p.dominated_by) by = label(*q.result);
                const double error = metric->percent ? 100 * p.error : p.error;
                html += fmt::format("<tr class=\"{}\">{}{}{}{}{}{}{}</tr>\n", p.dominated ? "dominated" : "front",
                                    cell(std::to_string(i + 1), true, double(i + 1)), cell(p.dominated ? "" : "yes"), cell(p.result->technique), cell(labels.parameters(*p.result)),
                                    cell(ratio_cell(p.time_ratio), true, p.time_ratio.value), cell(metric_cell(error), true, error),
                                    cell(by));
            }
            html += "</tbody></table></div></div>\n";
        }
    }
    if (html.empty()) return "";
    const std::string note = too_few_rounds_note(run);
    return "<h2 id=\"pareto\">Pareto fronts</h2>\n<p class=\"hint\">Per scene and resolution, on the error axes the "
           "techniques' families declare. A configuration is dominated when another is neither significantly worse in "
           "error nor significantly slower, and is significantly better in one of them: faster (the 95 % interval of their "
           "paired time ratio lies below 1) or lower in error by more than the metric's compare tolerance. Each point "
           "is numbered by its row (#) in the table below its chart; hover over it for its name. Filled: on the front; "
           "hollow: dominated; bars: 95 % interval of the time ratio; line: the front, from each configuration to the "
           "next slower one with a better error.</p>\n" +
           (note.empty() ? "" : "<p class=\"warning\" id=\"pareto-unjudged\">" + html_escape(note) + " No front line is drawn.</p>\n") +
           "<div class=\"charts\">\n" + html + "</div>\n";
}

std::string colour_bar(const std::array<ColormapEntry, 256>& colormap, double max_value, const std::string& what) {
    std::string stops;
    for (int i = 0; i <= 8; ++i) {
        const ColormapEntry& c = colormap[size_t(i * 255 / 8)];
        stops += fmt::format("{}rgb({},{},{}) {}%", i ? ", " : "", int(c[0] * 255 + 0.5f), int(c[1] * 255 + 0.5f),
                             int(c[2] * 255 + 0.5f), i * 100 / 8);
    }
    return fmt::format("<div class=\"bar\" style=\"background: linear-gradient(to right, {})\" title=\"{}\"></div>"
                       "<div class=\"bar-labels\"><span>0</span><span>{}</span><span>{}</span></div>",
                       stops, html_escape(what), html_escape(what), metric_cell(max_value));
}

std::string images_section(const RunRecord& run, const CaseLabels& labels, ImageStore& images) {
    std::string html;
    for (const CaseResult& c : run.cases) {
        if (c.image_png.empty()) continue;
        const ReferenceRecord* reference = nullptr;
        for (const ReferenceRecord& r : run.references)
            if (r.scene == c.scene && r.resolution.width == c.resolution.width && r.resolution.height == c.resolution.height)
                reference = &r;
        const int width = c.resolution.width;
        const auto panel = [&](const std::string& file, const std::string& name, const std::string& below) {
            const std::string img = images.img(file, name + ": " + c.id, width);
            if (img.empty()) return std::string("<div><div class=\"panel\"><span class=\"label\">" + name + ": none</span></div></div>");
            return fmt::format("<div><div class=\"panel\" style=\"--aspect: {} / {}\"><span class=\"label\">{}</span>{}</div>{}</div>",
                               c.resolution.width, c.resolution.height, name, img, below);
        };
        const std::string parameters = labels.parameters(c);  // "-": none shown, so none written
        html += fmt::format("<div class=\"case\" id=\"case-{}\"><h4><strong>{}</strong>{} — {}</h4>\n<div class=\"viewer\">",
                            html_escape(c.id), html_escape(c.technique),
                            parameters == "-" ? std::string() : fmt::format(" {}", html_escape(parameters)),
                            html_escape(c.group < run.groups.size() ? run.groups[c.group].name : c.scene));
        html += panel(c.image_png, "technique", "");
        html += panel(reference ? reference->image_png : "", "reference", "");
        html += panel(c.error_map_png, "error",
                      reference ? colour_bar(viridis_colormap(), reference->error_map_scale, "luminance error") : "");
        html += panel(c.flip_map_png, "FLIP", colour_bar(magma_colormap(), 1.0, "FLIP"));
        html += "</div></div>\n";
    }
    if (html.empty()) return "";
    return "<h2 id=\"images\">Images</h2>\n<p class=\"hint\">Technique | reference | luminance error | FLIP, per case. "
           "Wheel: zoom (the four panels together); drag: pan; double-click: reset.</p>\n" +
           html;
}

}  // namespace

std::string html_report(const RunRecord& run, const fs::path& run_dir, const HtmlReportOptions& options) {
    const CaseLabels labels(run.cases, TechniqueRegistry::instance());
    ImageStore images(run_dir, options.embed_images);
    // The sections this run has, in order, and a line of links to them.
    std::vector<std::pair<std::string, std::string>> sections = {{"environment", environment_section(run)},
                                                                 {"results", results_section(run, labels)},
                                                                 {"Pareto fronts", pareto_section(run, labels, options.pareto_metrics)}};
    std::error_code error;
    if (fs::is_regular_file(run_dir / "paper.md", error))
        sections.emplace_back("paper", "<h2 id=\"paper\">Paper comparison</h2>\n" +
                                           markdown_to_html(read_bytes(run_dir / "paper.md"), 2));
    sections.emplace_back("images", images_section(run, labels, images));
    std::string links, content;
    for (const auto& [name, html] : sections) {
        if (html.empty()) continue;
        const std::string anchor = name == "Pareto fronts" ? "pareto" : name;
        links += fmt::format("{}<a href=\"#{}\">{}</a>", links.empty() ? "" : " · ", anchor, name);
        content += html;
    }
    const std::string body = fmt::format("<h1>{}</h1>\n<p>{}</p>\n<p class=\"hint\">{}</p>\n{}", html_escape(run.experiment),
                                         html_escape(run.description), links, content);
    return fmt::format("<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>{} — canopy "
                       "report</title>\n<style>{}</style>\n</head>\n<body>\n{}<pre id=\"selftest-result\"></pre>\n{}<script>{}"
                       "</script>\n</body>\n</html>\n",
                       html_escape(run.experiment), report_page_style(), body, images.blocks(), report_page_script());
}

void write_html_report(const fs::path& run_dir, const fs::path& out, const HtmlReportOptions& options) {
    for (const std::string& metric : options.pareto_metrics)
        if (!find_metric(metric))
            throw std::invalid_argument(fmt::format("no error metric '{}': `canopy metrics` lists their results.json names",
                                                    metric));
    const RunRecord run = read_json_report(run_dir / "results.json");
    write_text_atomically(out, html_report(run, run_dir, options));
}

}  // namespace canopy
