// Unreal Engine nDisplay's .ndisplay configuration (version 5.x: nDisplay.cluster.nodes, each
// with its host, its window on the desktop and its viewports, each viewport's region in the
// window's pixels): every viewport a display, placed on the canvas at its window's position
// plus its region's; one pipeserver per node. Projection policies, cameras and warp meshes
// shape what a viewport renders, not where it is: they are named in the notes.
#include <fmt/format.h>

#include <cmath>
#include <map>
#include <vector>

#include "import_formats.hpp"

namespace l2 {
namespace {

constexpr int kMaxPosition = 65536;  // desktop coordinates, before the canvas is moved to 0,0

struct Rectangle {
  int x = 0, y = 0, w = 0, h = 0;
};

Rectangle read_rectangle(const JsonAt& r, int most) {
  r.object();
  return {static_cast<int>(r["x"].integer(-kMaxPosition, kMaxPosition)),
          static_cast<int>(r["y"].integer(-kMaxPosition, kMaxPosition)), r["w"].positive(most),
          r["h"].positive(most)};
}

// A viewport's remap (the config asset's Viewport Remap, Base Remap: Angle, Flip H, Flip V),
// as the panel hangs: turned by the angle, mirrored by the flips; both flips are a half turn.
Orientation read_remap(const JsonAt& remap) {
  Orientation o;
  if (!remap.present() || !remap["bEnable"].boolean_or(false)) return o;
  const JsonAt base = remap["baseRemap"];
  const JsonAt angle = base["angle"];
  const double a = angle.number_or(0);
  const double turns = a / 90;
  if (std::abs(turns - std::round(turns)) > 1e-6 || std::abs(turns) > 1e6) {
    angle.expected("0, 90, 180 or 270 (a display hangs turned by quarter turns)");
  }
  int rotation = static_cast<int>(std::lround(turns)) % 4;
  rotation = (rotation + 4) % 4 * 90;
  const bool h = base["bFlipH"].boolean_or(false), v = base["bFlipV"].boolean_or(false);
  if (h && v) {
    rotation = (rotation + 180) % 360;
  } else if (h) {
    o.flip = Flip::Horizontal;
  } else if (v) {
    o.flip = Flip::Vertical;
  }
  o.rotation = rotation;
  return o;
}

std::string joined(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) out += (i == 0 ? "" : ", ") + names[i];
  return out;
}

}  // namespace

WallDraft import_ndisplay(const JsonAt& root, const std::string& name) {
  const std::string& file = root.file();
  const JsonAt nd = root["nDisplay"];
  nd.object();
  const JsonAt nodes = nd["cluster"]["nodes"];
  // Counted before anything is made of them: a file of thousands is refused as it is.
  long long viewports = 0;
  for (const auto& item : nodes.object().items()) {
    const JsonAt vps = nodes[item.key()]["viewports"];
    viewports += static_cast<long long>(vps.object().size());
  }
  if (viewports > kMaxImportedDisplays) too_many_displays(file, nodes.path(), viewports);

  WallDraft d;
  d.name = name;
  d.header.push_back(
      fmt::format("Imported by tilelayout import from {} (nDisplay configuration, "
                  "version {}).",
                  file, nd["version"].string_or("not given")));
  d.header.push_back(
      "Each viewport is a display at its node's window position plus its region in the window.");
  std::map<std::string, std::vector<std::string>> policies, cameras;
  for (const auto& node_item : nodes.object().items()) {
    const std::string& node_name = node_item.key();
    const JsonAt node = nodes[node_name];
    const std::string host = node["host"].string();
    const Rectangle window = read_rectangle(node["window"], kMaxPosition);
    d.hosts.push_back(host);
    const JsonAt remap = node["outputRemap"];
    if (remap.present() && remap["bEnable"].boolean_or(false)) {
      const std::string source = remap["dataSource"].string_or("mesh");
      const std::string what = source == "file"   ? remap["externalFile"].string_or("")
                               : source == "mesh" ? remap["staticMeshAsset"].string_or("")
                                                  : "";
      d.notes.push_back(fmt::format(
          "node {}: output remap from {} {}: a warp of the node's whole output, not carried; its "
          "viewports are imported unwarped",
          node_name, source, what.empty() ? "(none named)" : "\"" + what + "\""));
    }
    const JsonAt vps = node["viewports"];
    for (const auto& vp_item : vps.object().items()) {
      const std::string& vp_name = vp_item.key();
      const JsonAt vp = vps[vp_name];
      vp.object();
      const Rectangle region = read_rectangle(vp["region"], kMaxImportedSide);
      const std::string where = fmt::format("{}/{}", node_name, vp_name);
      const std::string policy = vp["projectionPolicy"]["type"].string_or("");
      if (!policy.empty()) policies[policy].push_back(where);
      const std::string camera = vp["camera"].string_or("");
      if (!camera.empty()) cameras[camera].push_back(where);
      DraftDisplay p;
      p.orientation = read_remap(vp["viewportRemap"]);
      // The region is the picture as seen; a turned panel's native raster is it turned.
      p.width = p.orientation.turned() ? region.h : region.w;
      p.height = p.orientation.turned() ? region.w : region.h;
      p.x = window.x + region.x;
      p.y = window.y + region.y;
      p.origin = fmt::format(
          "viewport {} of node {} on {}: region {}x{} at {},{} of its window "
          "at {},{}",
          vp_name, node_name, host, region.w, region.h, region.x, region.y, window.x, window.y);
      if (p.orientation.rotation != 0 || p.orientation.flip != Flip::None) {
        d.notes.push_back(fmt::format(
            "viewport {}: remap angle and flips read as the panel turned {} degrees clockwise{}; "
            "if the picture comes out turned the other way, use rotation = {}",
            where, p.orientation.rotation,
            p.orientation.flip == Flip::None
                ? ""
                : fmt::format(" then mirrored {}",
                              kFlipNames[static_cast<int>(p.orientation.flip)]),
            (360 - p.orientation.rotation) % 360));
      }
      d.displays.push_back(p);
    }
  }
  if (d.displays.empty()) nodes.fail("expected nodes with viewports, got none");
  for (const auto& [policy, where] : policies) {
    d.notes.push_back(fmt::format(
        "projection policy \"{}\" ({}): not carried; each display shows its canvas rectangle",
        policy, joined(where)));
  }
  for (const auto& [camera, where] : cameras) {
    d.notes.push_back(fmt::format("camera \"{}\" ({}): not carried", camera, joined(where)));
  }
  return d;
}

}  // namespace l2
