#include "scenario/fracture_sources.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <sstream>

#include "geometry/trace_crossings.hpp"
#include "scenario/input_files.hpp"
#include "scenario/validation.hpp"

namespace hydrodda::scenario {

namespace {

// More traces than the cutting handles in reasonable time (a few thousand take a second).
constexpr double kMaxTracesPerSet = 100'000;
// Bad rows of a fractures file reported one by one; a file of many is likely no such file at all.
constexpr int kMaxRowErrors = 20;
// A fractures file's limits: its rows, and the blocks its traces could make (estimated from
// their crossings): 10^6 blocks take some 35 s and 1.5 GB to cut, and are past what a model runs.
constexpr std::size_t kMaxFileTraces = 100'000;
constexpr double kMaxFileBlocks = 1e6;

std::string_view trim(std::string_view s) {
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.front()))) s.remove_prefix(1);
  while (!s.empty() && std::isspace(static_cast<unsigned char>(s.back()))) s.remove_suffix(1);
  return s;
}

// A field of a row: a finite number (`value`), a number a double cannot hold ("1e400"), one
// that is not finite ("nan", "inf"), a number followed by more ("1 2", "3m"), or text.
enum class FieldKind { number, out_of_range, not_finite, partial, text };

FieldKind read_field(std::string_view field, double& value) {
  if (field.size() > 1 && field.front() == '+' && field[1] != '-') field.remove_prefix(1);
  const auto [end, error] = std::from_chars(field.data(), field.data() + field.size(), value);
  if (field.empty() || error == std::errc::invalid_argument) return FieldKind::text;
  if (end != field.data() + field.size()) return FieldKind::partial;
  if (error == std::errc::result_out_of_range) return FieldKind::out_of_range;
  return std::isfinite(value) ? FieldKind::number : FieldKind::not_finite;
}

// A row split at its commas, each field trimmed.
std::vector<std::string_view> split_fields(std::string_view line) {
  std::vector<std::string_view> fields;
  for (;;) {
    const std::size_t comma = line.find(',');
    fields.push_back(trim(line.substr(0, comma)));
    if (comma == std::string_view::npos) return fields;
    line.remove_prefix(comma + 1);
  }
}

// A row as quoted in a message: a line of a file that is not CSV may be long.
std::string quote_row(std::string_view line) {
  constexpr std::size_t kShown = 60;
  return line.size() <= kShown ? fmt::format("\"{}\"", line) : fmt::format("\"{}...\"", line.substr(0, kShown));
}

// What a row is: a header (a first row with no number in it), a trace, or a problem to report.
struct ReadRow {
  bool header = false;
  std::optional<Segment> trace;
  std::string problem;
  std::string joint;  // the fifth column, when given
};

ReadRow read_row(std::string_view line, bool may_be_header) {
  static constexpr const char* kColumns[] = {"x1", "y1", "x2", "y2"};
  const std::vector<std::string_view> fields = split_fields(line);
  std::vector<double> values(fields.size());
  std::vector<FieldKind> kinds;
  for (std::size_t i = 0; i < fields.size(); ++i) kinds.push_back(read_field(fields[i], values[i]));
  if (may_be_header && std::all_of(kinds.begin(), kinds.end(), [](FieldKind k) { return k == FieldKind::text; }))
    return {true, std::nullopt, {}};
  const std::string expected = "expected four numbers x1,y1,x2,y2, got " + quote_row(line);
  // The optional fifth column names the trace's joint type ([joint.NAME]); empty: [joint].
  std::string joint;
  if (fields.size() == 5) {
    joint = std::string(fields[4]);
    kinds.pop_back();
  }
  if ((fields.size() != 4 && fields.size() != 5) || std::any_of(kinds.begin(), kinds.end(), [](FieldKind k) {
        return k == FieldKind::text || k == FieldKind::partial;
      }))
    return {false, std::nullopt, expected};
  for (std::size_t i = 0; i < 4; ++i) {
    if (kinds[i] == FieldKind::out_of_range)
      return {false, std::nullopt, fmt::format("{}: {} = {} is beyond the range of a number (about 1e-308 to 1e308)", expected,
                                        kColumns[i], fields[i])};
    if (kinds[i] == FieldKind::not_finite)
      return {false, std::nullopt, fmt::format("{}: {} = {} is not a finite number", expected, kColumns[i], fields[i])};
  }
  return {false, Segment{{values[0], values[1]}, {values[2], values[3]}}, {}, std::move(joint)};
}

// Refuses a fractures file of more rows than can be cut, or of traces that would cross into
// more blocks than can be made, before any cutting (the crossings are estimated over the part
// of the domain's box the traces span).
void check_file_size(ReadContext& ctx, int line, const std::string& key, const std::filesystem::path& path,
                     const GeometryDefinition& geometry) {
  const std::vector<FileFracture>& rows = geometry.file_fractures;
  if (rows.size() > kMaxFileTraces) {
    ctx.error(line, key, fmt::format("{} holds {} traces; at most {} can be cut into blocks", path.string(),
                                     rows.size(), kMaxFileTraces));
    return;
  }
  std::vector<geometry::Segment2> traces;
  geometry::Box span;
  for (const FileFracture& f : rows) {
    traces.push_back({f.segment.from, f.segment.to});
    span.add(f.segment.from);
    span.add(f.segment.to);
  }
  if (geometry.domain.size() >= 3) {
    const geometry::Box domain = geometry::bounding_box(geometry.domain);
    span.lo = {std::max(span.lo.x, domain.lo.x), std::max(span.lo.y, domain.lo.y)};
    span.hi = {std::min(span.hi.x, domain.hi.x), std::min(span.hi.y, domain.hi.y)};
  }
  const double blocks = geometry::estimate_crossings(traces, span);
  if (blocks > kMaxFileBlocks)
    ctx.error(line, key,
              fmt::format("the {} traces of {} would cut the domain into some {:.2g} blocks (as often as they would "
                          "cross, spread evenly over the {:.3g} m x {:.3g} m they span); at most {:g} can be made",
                          rows.size(), path.string(), blocks, span.width(), span.height(), kMaxFileBlocks));
}

}  // namespace

void read_joint_sets(ReadContext& ctx, const TableView& g, GeometryDefinition& geometry) {
  int index = 0;
  for (const toml::table* table : g.tables("joint_set")) {
    ++index;
    const TableView j(ctx, *table, "geometry.joint_set",
                      {"angle", "spacing", "angle_spread", "spacing_spread", "length", "length_spread", "gap",
                       "gap_spread", "offset", "region", "seed", "joint"});
    JointSetDefinition set;
    set.line = j.line();
    if (auto joint = j.string("joint")) set.joint = {*joint, j.line_of_key("joint")};
    for (const char* key : {"angle", "spacing"})
      if (!j.has(key)) ctx.error(j.line(), j.key_path(key), "required key is missing");
    set.angle = j.number("angle").value_or(0.0);
    set.spacing = j.number("spacing").value_or(0.0);
    if (j.has("spacing")) j.require("spacing", set.spacing > 0.0, "must be > 0");
    const auto spread = [&](const char* key) {
      const double v = j.number(key).value_or(0.0);
      j.require(key, v >= 0.0, "must be >= 0");
      return v;
    };
    set.angle_spread = spread("angle_spread");
    set.spacing_spread = spread("spacing_spread");
    set.length_spread = spread("length_spread");
    set.gap_spread = spread("gap_spread");
    set.length = j.number("length");
    if (set.length) j.require("length", *set.length > 0.0, "must be > 0");
    set.gap = j.number("gap");
    if (set.gap) j.require("gap", *set.gap > 0.0, "must be > 0");
    for (const char* key : {"length_spread", "gap", "gap_spread"})
      if (j.has(key) && !j.has("length"))
        ctx.error(j.line_of_key(key), j.key_path(key), "applies to traces of a given length: give 'length' too");
    set.offset = j.number("offset");
    if (set.offset) j.require("offset", *set.offset >= 0.0, "must be >= 0");
    const std::string indexed = fmt::format("geometry.joint_set[{}]", index - 1);
    if (!j.has("offset")) ctx.defaults.push_back({indexed + ".offset", format_number(0.5 * set.spacing) + " (spacing / 2)"});
    if (set.length && !j.has("gap")) ctx.defaults.push_back({indexed + ".gap", format_number(*set.length) + " (length)"});
    if (auto region = j.points("region")) {
      set.region = std::move(*region);
      if (check_polygon(ctx, j.line_of_key("region"), j.key_path("region"), set.region) &&
          geometry.domain.size() >= 3 && !polygons_overlap(set.region, geometry.domain))
        ctx.error(j.line_of_key("region"), j.key_path("region"),
                  "the set's region lies wholly outside geometry.domain, so none of its joints would cut it");
    }
    if (auto seed = j.integer("seed", 0, std::numeric_limits<int>::max())) {
      set.seed = static_cast<std::uint64_t>(*seed);
    } else if (!j.has("seed")) {
      ctx.defaults.push_back({indexed + ".seed", "0"});
    }
    // A guard against a spacing meant in other units: the traces the set would make, roughly
    // (joints across the region's box diagonal, each cut into traces and gaps along it).
    const Polygon& region = set.region.empty() ? geometry.domain : set.region;
    if (set.spacing > 0.0 && region.size() >= 3) {
      const geometry::Box box = geometry::bounding_box(region);
      const double diagonal = std::hypot(box.width(), box.height());
      const double per_joint = set.length ? diagonal / (*set.length + set.gap.value_or(*set.length)) + 1.0 : 1.0;
      const double traces = diagonal / set.spacing * per_joint;
      if (traces > kMaxTracesPerSet)
        ctx.error(j.line_of_key("spacing"), j.key_path("spacing"),
                  fmt::format("the set would make some {:.3g} traces; at most {:g} can be cut into blocks", traces,
                              kMaxTracesPerSet));
    }
    geometry.joint_sets.push_back(std::move(set));
  }
}

void read_fractures_file(ReadContext& ctx, const TableView& g, const std::filesystem::path& scenario_file,
                         GeometryDefinition& geometry) {
  const auto name = g.string("fractures_file");
  if (!name) return;
  const int line = g.line_of_key("fractures_file");
  const std::string key = g.key_path("fractures_file");
  std::filesystem::path path(*name);
  if (path.is_relative()) path = scenario_file.parent_path() / path;
  geometry.fractures_file = path;
  if (!check_named_file(ctx, line, key, path, kMaxFracturesFileBytes)) return;
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ctx.error(line, key, fmt::format("cannot read {}", path.string()));
    return;
  }
  std::ostringstream text;
  text << in.rdbuf();
  geometry.file_fractures = parse_fracture_rows(text.str(), path.string(), key, ctx.errors);
  if (geometry.file_fractures.empty())
    ctx.error(line, key, fmt::format("{} holds no fracture rows x1,y1,x2,y2", path.string()));
  else
    check_file_size(ctx, line, key, path, geometry);
  check_file_traces_meet_domain(ctx, path.string(), key, geometry);
}

void check_file_traces_meet_domain(ReadContext& ctx, const std::string& file, const std::string& key,
                                   const GeometryDefinition& geometry) {
  int outside = 0;
  for (const FileFracture& f : geometry.file_fractures) {
    if (segment_meets_polygon(f.segment.from, f.segment.to, geometry.domain)) continue;
    if (++outside <= kMaxRowErrors) ctx.errors.push_back({file, f.line, key, "the trace lies wholly outside geometry.domain"});
  }
  if (outside > kMaxRowErrors)
    ctx.errors.push_back({file, 0, key, fmt::format("{} of its {} traces lie wholly outside geometry.domain (the first {} "
                                                    "are named above)", outside, geometry.file_fractures.size(), kMaxRowErrors)});
}

std::vector<FileFracture> parse_fracture_rows(std::string_view text, const std::string& file, const std::string& key,
                                              std::vector<Diagnostic>& errors) {
  std::vector<FileFracture> rows;
  int line_number = 0;
  bool first_content = true;
  int reported = 0;
  const auto error = [&](std::string message) {
    if (++reported <= kMaxRowErrors) errors.push_back({file, line_number, key, std::move(message)});
    else if (reported == kMaxRowErrors + 1) errors.push_back({file, line_number, key, "more bad rows follow; fix these first"});
  };
  while (!text.empty()) {
    const std::size_t end = text.find('\n');
    const std::string_view line = trim(text.substr(0, end));
    text.remove_prefix(end == std::string_view::npos ? text.size() : end + 1);
    ++line_number;
    if (line.empty() || line.front() == '#') continue;
    const ReadRow row = read_row(line, first_content);
    first_content = false;
    if (row.header) continue;
    if (!row.trace) {
      error(row.problem);
      continue;
    }
    const Point from = row.trace->from, to = row.trace->to;
    if (from == to) {
      error("the trace's two end points coincide");
      continue;
    }
    rows.push_back({{from, to}, line_number, row.joint});
  }
  return rows;
}

}  // namespace hydrodda::scenario
