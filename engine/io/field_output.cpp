#include "io/field_output.hpp"

#include <filesystem>
#include <fstream>

#include "core/error.hpp"
#include "io/h5_archive.hpp"
#include "io/temp_file.hpp"

namespace edem {
namespace {

namespace fs = std::filesystem;

bool ends_with_any(const std::string& s, std::initializer_list<std::string_view> endings) {
  for (auto e : endings)
    if (s.ends_with(e)) return true;
  return false;
}

// A DataItem of dataset `path` in `file`, `dims` as "N" or "N 3".
std::string data_item(const std::string& file, const std::string& path, const std::string& dims,
                      const std::string& type) {
  const std::string number = type == "Int" ? R"(NumberType="Int" Precision="4")" : R"(NumberType="Float" Precision="8")";
  return fmt::format(R"(<DataItem Dimensions="{}" {} Format="HDF">{}:{}</DataItem>)", dims, number, file, path);
}

// XML's special characters in an attribute value.
std::string xml_escaped(const std::string& text) {
  std::string out;
  for (const char c : text) {
    if (c == '&') out += "&amp;";
    else if (c == '<') out += "&lt;";
    else if (c == '>') out += "&gt;";
    else if (c == '"') out += "&quot;";
    else out += c;
  }
  return out;
}

// A scalar attribute; with a legend (what its integers mean) as an Information element.
std::string attribute(const std::string& file, const std::string& group, const std::string& name, int count,
                      const char* center, const std::string& type, const std::string& legend = "") {
  const std::string information =
      legend.empty() ? "" : fmt::format(R"(<Information Name="legend" Value="{}"/>)", xml_escaped(legend));
  return fmt::format(R"(        <Attribute Name="{}" AttributeType="Scalar" Center="{}">{}{}</Attribute>
)",
                     name, center, information, data_item(file, group + "/" + name, std::to_string(count), type));
}

std::string displacement_attribute(const std::string& file, const std::string& group, int points) {
  return fmt::format(R"(        <Attribute Name="displacement" AttributeType="Vector" Center="Node">{}</Attribute>
)",
                     data_item(file, group + "/displacement", fmt::format("{} 3", points), "Float"));
}

struct Field {
  std::string name, type, legend;
};

// A grid of line cells (two points each) with its cell attributes and its points' displacement;
// none when there are no cells.
std::string line_grid(const std::string& file, const std::string& group, const char* name, int cells,
                      const std::vector<Field>& fields) {
  if (cells == 0) return "";  // readers stumble on empty data items; the frame simply has none
  std::string text = fmt::format(R"(      <Grid Name="{}" GridType="Uniform">
        <Topology TopologyType="Polyline" NodesPerElement="2" NumberOfElements="{}">{}</Topology>
        <Geometry GeometryType="XY">{}</Geometry>
)",
                                 name, cells, data_item(file, group + "/cells", fmt::format("{} 2", cells), "Int"),
                                 data_item(file, group + "/points", fmt::format("{} 2", 2 * cells), "Float"));
  text += displacement_attribute(file, group, 2 * cells);
  for (const auto& f : fields) text += attribute(file, group, f.name, cells, "Cell", f.type, f.legend);
  return text + "      </Grid>\n";
}

std::string material_legend(const std::vector<std::string>& names) {
  std::string legend;
  for (size_t i = 0; i < names.size(); ++i) legend += fmt::format("{}{} {}", i > 0 ? ", " : "", i, names[i]);
  return legend;
}

// Point pairs' connectivity: 0 1, 2 3, ...
std::vector<std::array<int, 2>> pairs(size_t points) {
  std::vector<std::array<int, 2>> cells(points / 2);
  for (size_t i = 0; i < cells.size(); ++i) cells[i] = {static_cast<int>(2 * i), static_cast<int>(2 * i + 1)};
  return cells;
}

}  // namespace

FieldSeries::FieldSeries(std::string xdmf) : xdmf_(std::move(xdmf)) {
  if (!ends_with_any(xdmf_, {".xdmf", ".xmf"}))
    fail("the output file '{}' must end in .xdmf or .xmf (the data go beside it in .h5)", xdmf_);
  data_ = fs::path(xdmf_).replace_extension(".h5").string();
  const fs::path parent = fs::path(xdmf_).parent_path();
  std::error_code ec;
  if (!parent.empty() && !fs::is_directory(parent, ec))
    fail("cannot write '{}': directory '{}' does not exist", xdmf_, parent.string());
}

void FieldSeries::append(const FieldFrame& f) {
  const h5::QuietErrors quiet;
  h5::Handle file;
  if (index_.empty()) {
    file = h5::Handle(H5Fcreate(data_.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT), H5Fclose);
    if (file.get() >= 0) h5::create_group(file.get(), "frames", data_);
  } else {
    file = h5::Handle(H5Fopen(data_.c_str(), H5F_ACC_RDWR, H5P_DEFAULT), H5Fclose);
  }
  if (file.get() < 0) fail("cannot write '{}': HDF5 could not open it", data_);
  const int number = frames() + 1;
  const std::string name = fmt::format("/frames/{}", number);
  const h5::Handle frame_group = h5::create_group(file.get(), name.c_str(), data_ + ":" + name);
  h5::Writer frame(frame_group.get(), name);
  frame("time", f.time);
  frame("cycle", f.cycle);
  frame("stage", f.stage);
  {
    const h5::Handle g = frame.group("zones");
    h5::Writer w(g.get(), name + "/zones");
    w("points", f.points);
    w("cells", f.triangles);
    w("displacement", f.displacement);
    w("velocity", f.velocity);
    w("sxx", f.sxx), w("syy", f.syy), w("sxy", f.sxy), w("szz", f.szz), w("s1", f.s1), w("s3", f.s3);
    w("state", f.state), w("material", f.material), w("block", f.block);
    w("state_legend", std::string(kStateLegend));
    w("material_legend", material_legend(f.material_names));
  }
  {
    const h5::Handle g = frame.group("contacts");
    h5::Writer w(g.get(), name + "/contacts");
    w("points", f.contact_points), w("cells", pairs(f.contact_points.size()));
    w("displacement", f.contact_displacement);
    w("fn", f.fn), w("fs", f.fs), w("un", f.un), w("us", f.us), w("slip", f.slip);
    w("state", f.contact_state), w("kind", f.contact_kind);
    w("state_legend", std::string(kContactStateLegend)), w("kind_legend", std::string(kContactKindLegend));
  }
  {
    const h5::Handle g = frame.group("cracks");
    h5::Writer w(g.get(), name + "/cracks");
    w("points", f.crack_points), w("cells", pairs(f.crack_points.size()));
    w("displacement", f.crack_displacement);
    w("mode", f.crack_mode), w("cycle", f.crack_cycle), w("stage", f.crack_stage);
    w("mode_legend", std::string(kCrackModeLegend));
  }
  {
    const h5::Handle g = frame.group("bolts");
    h5::Writer w(g.get(), name + "/bolts");
    w("points", f.bolt_points), w("cells", pairs(f.bolt_points.size()));
    w("displacement", f.bolt_displacement);
    w("force", f.bolt_force), w("strain", f.bolt_strain), w("state", f.bolt_state);
    w("state_legend", std::string(kBoltStateLegend));
  }
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0) fail("cannot write '{}': HDF5 could not flush it", data_);
  index_.push_back({f.time, static_cast<int>(f.triangles.size()), static_cast<int>(f.points.size()),
                    static_cast<int>(f.contact_points.size() / 2), static_cast<int>(f.crack_points.size() / 2),
                    static_cast<int>(f.bolt_points.size() / 2), material_legend(f.material_names)});
  write_index();
}

void FieldSeries::write_index() const {
  // The index names the data file relative to itself (they sit side by side).
  const std::string file = fs::path(data_).filename().string();
  std::string text = R"(<?xml version="1.0" ?>
<Xdmf Version="3.0">
  <Domain>
    <Grid Name="EDEM" GridType="Collection" CollectionType="Temporal">
)";
  for (size_t i = 0; i < index_.size(); ++i) {
    const Entry& e = index_[i];
    const std::string g = fmt::format("/frames/{}", i + 1), z = g + "/zones";
    text += fmt::format(R"(    <Grid Name="frame {}" GridType="Collection" CollectionType="Spatial">
      <Time Value="{}"/>
      <Grid Name="zones" GridType="Uniform">
        <Topology TopologyType="Triangle" NumberOfElements="{}">{}</Topology>
        <Geometry GeometryType="XY">{}</Geometry>
        <Attribute Name="displacement" AttributeType="Vector" Center="Node">{}</Attribute>
        <Attribute Name="velocity" AttributeType="Vector" Center="Node">{}</Attribute>
)",
                        i + 1, e.time, e.zones, data_item(file, z + "/cells", fmt::format("{} 3", e.zones), "Int"),
                        data_item(file, z + "/points", fmt::format("{} 2", e.points), "Float"),
                        data_item(file, z + "/displacement", fmt::format("{} 3", e.points), "Float"),
                        data_item(file, z + "/velocity", fmt::format("{} 3", e.points), "Float"));
    for (const char* field : {"sxx", "syy", "sxy", "szz", "s1", "s3"})
      text += attribute(file, z, field, e.zones, "Cell", "Float");
    text += attribute(file, z, "state", e.zones, "Cell", "Int", kStateLegend);
    text += attribute(file, z, "material", e.zones, "Cell", "Int", e.materials);
    text += attribute(file, z, "block", e.zones, "Cell", "Int");
    text += "      </Grid>\n";
    text += line_grid(file, g + "/contacts", "contacts", e.contacts,
                      {{"fn", "Float", ""}, {"fs", "Float", ""}, {"un", "Float", ""}, {"us", "Float", ""},
                       {"slip", "Float", ""}, {"state", "Int", kContactStateLegend}, {"kind", "Int", kContactKindLegend}});
    text += line_grid(file, g + "/cracks", "cracks", e.cracks,
                      {{"mode", "Int", kCrackModeLegend}, {"cycle", "Float", ""}, {"stage", "Int", ""}});
    text += line_grid(file, g + "/bolts", "bolts", e.bolt_segments,
                      {{"force", "Float", ""}, {"strain", "Float", ""}, {"state", "Int", kBoltStateLegend}});
    text += "    </Grid>\n";
  }
  text += "    </Grid>\n  </Domain>\n</Xdmf>\n";
  TempFile tmp(xdmf_);
  {
    std::ofstream out(tmp.path());
    out << text;
    if (!out) fail("cannot write '{}'", xdmf_);
  }
  tmp.move_into_place();
}

}  // namespace edem
