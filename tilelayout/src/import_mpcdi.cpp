// VESA MPCDI (Multiple Projection Common Data Interchange), the 2D media profile, versions 1.0
// and 2.0: mpcdi.xml's display holds buffers (one picture each), a buffer holds regions (one
// projector each: where in the buffer it shows, normalised 0..1, and its raster), and files
// holds one fileset per region naming its geometry warp (PFM), alpha map and beta map (PNG) in
// the archive. Every region becomes a [[display]] at its place in the buffer, scaled to the
// buffer's pixels, with `warp`, `alpha`, `alpha_gamma` and `beta` naming the files as they will
// be extracted beside the wall file. The 3D, advanced 3D and shader-lamp profiles describe what
// a projector renders from a 3D scene, which a wall of 2D pictures cannot carry: refused.
#include <fmt/format.h>
#include <tinyxml2.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

#include "import_draft.hpp"
#include "mpcdi_xml.hpp"
#include "tilelayout/tile_layout.hpp"
#include "tilelayout/toml_text.hpp"
#include "tilelayout/wall_import.hpp"

namespace l2 {
namespace {

constexpr std::size_t kMaxXmlBytes = 16 << 20;  // far more than any calibration's mpcdi.xml
constexpr int kMaxBufferSide = 16384;           // a buffer is at most a wall's canvas
constexpr std::size_t kMaxIdInName = 32;        // of a region's id in an extracted file's name

// The profiles MPCDI defines, as its root's `profile` attribute names them.
std::string_view profile_name(std::string_view p) {
  if (p == "3d") return "the 3D media profile";
  if (p == "a3") return "the advanced 3D profile";
  if (p == "sl") return "the shader lamp profile";
  return "";
}

std::string lowered(std::string s) {
  for (char& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

// A region's id as part of a file name: letters, digits, '-' and '_' kept, the rest '_'.
std::string name_part(const std::string& id) {
  std::string out;
  for (const char c : id.substr(0, kMaxIdInName))
    out += std::isalnum(static_cast<unsigned char>(c)) || c == '-' ? c : '_';
  return out;
}

struct Context {
  const std::vector<std::string>& entries;
  const MpcdiImport& options;
  WallDraft& draft;
  std::vector<ExtractedFile>& files;
};

// The root: an MPCDI document of the 2D media profile, of a version this importer knows.
std::string check_root(const XmlAt& root, WallDraft& draft) {
  const std::optional<std::string> profile = root.attribute("profile");
  if (!profile) root.fail("profile", "missing: expected profile=\"2d\" (the 2D media profile)");
  const std::string p = lowered(*profile);
  if (p != "2d") {
    const std::string_view known = profile_name(p);
    root.fail(
        "profile",
        fmt::format("{}{}: tilelayout import takes the 2D media profile only (profile=\"2d\": "
                    "regions of one flat picture), not a projection of a 3D scene",
                    quoted_value(*profile), known.empty() ? "" : " is " + std::string(known)));
  }
  const std::optional<std::string> version = root.attribute("version");
  if (!version) {
    draft.notes.push_back("the MPCDI element has no version: read as 2.0");
    return "2.0";
  }
  if (*version != "1.0" && *version != "2.0" && *version != "1" && *version != "2")
    root.fail("version", fmt::format("expected 1.0 or 2.0, got {}", quoted_value(*version)));
  return *version;
}

void note_unused(const XmlAt& at, const std::vector<std::string>& used, WallDraft& draft) {
  for (const std::string& name : at.child_names()) {
    if (std::find(used.begin(), used.end(), name) != used.end()) continue;
    draft.notes.push_back(
        fmt::format("{}.{}: not carried (the wall file has no place for it)", at.path(), name));
  }
}

// The path a fileset's element names, which the archive must hold; the name it is given.
// The key line that names it: `key = "FOLDER/dN-ID-KIND.EXT"  # ENTRY: PATH`.
// `map`: an alpha or beta map, which must be the display's size.
std::string archive_file(const XmlAt& element, const Context& c, int display, const std::string& id,
                         std::string_view kind, std::string_view ext,
                         const DraftDisplay* map = nullptr) {
  std::string path = element.child_text("path");
  const std::string entry = path.rfind("./", 0) == 0 ? path.substr(2) : path;
  if (std::find(c.entries.begin(), c.entries.end(), entry) == c.entries.end())
    element.child("path").fail("", fmt::format("{} is not in the archive", quoted_value(path)));
  const std::string out =
      fmt::format("{}/d{}-{}-{}.{}", c.options.maps_folder, display, name_part(id), kind, ext);
  c.files.push_back({entry, out, map ? map->width : 0, map ? map->height : 0});
  return fmt::format("{} = {}  # {} of the archive: {}", kind, toml_quoted(out),
                     quoted_value(entry), element.path());
}

// componentDepth 1 (grey) and bitDepth 8 or 16 of an alpha or beta map.
void check_depths(const XmlAt& map, WallDraft& draft) {
  const double components = map.child_number_or("componentDepth", 1, 3, 1);
  if (components != 1) {
    map.child("componentDepth")
        .fail("", fmt::format("{} (a colour map): the wall's alpha and beta maps are grey "
                              "(componentDepth 1)",
                              components));
  }
  const double bits = map.child_number_or("bitDepth", 8, 16, 8);
  if (bits != 8 && bits != 16)
    map.child("bitDepth").fail("", fmt::format("expected 8 or 16, got {}", bits));
  if (bits == 16) {
    draft.notes.push_back(fmt::format(
        "{}: a 16-bit map, read rounded to 8 bits (its finer steps are not kept)", map.path()));
  }
}

void read_alpha(const XmlAt& alpha, const Context& c, int display, const std::string& id,
                DraftDisplay& d) {
  check_depths(alpha, c.draft);
  d.keys.push_back(archive_file(alpha, c, display, id, "alpha", "png", &d));
  const double gamma = c.options.display_gamma;
  const double embedded = alpha.child_number_or("gammaEmbedded", 0.1, 10, gamma);
  if (!alpha.child("gammaEmbedded").present()) {
    c.draft.notes.push_back(
        fmt::format("{}: no gammaEmbedded: taken as the display's gamma {} (the map used as it is)",
                    alpha.path(), gamma));
  }
  const double alpha_gamma = gamma / embedded;
  if (alpha_gamma < 1 - 1e-9 || alpha_gamma > 4 + 1e-9) {
    alpha.child("gammaEmbedded")
        .fail("", fmt::format("{} on projectors of gamma {} makes alpha_gamma {:.3g}, outside the "
                              "1..4 a wall takes (--display-gamma sets the projectors' gamma)",
                              embedded, gamma, alpha_gamma));
  }
  if (std::abs(alpha_gamma - 1) > 1e-9) {
    d.keys.push_back(fmt::format("alpha_gamma = {:.6g}  # display gamma {} / gammaEmbedded {}",
                                 alpha_gamma, gamma, embedded));
  }
}

void read_fileset(const XmlAt& fileset, const Context& c, int display, const std::string& id,
                  DraftDisplay& d) {
  const XmlAt warp = fileset.child("geometryWarpFile");
  if (warp.present()) {
    d.keys.push_back(archive_file(warp, c, display, id, "warp", "pfm"));
    const std::string interpolation = lowered(warp.child("interpolation").text());
    if (!interpolation.empty() && interpolation != "linear") {
      c.draft.notes.push_back(
          fmt::format("{}.interpolation: {}: the wall samples its warps linearly", warp.path(),
                      quoted_value(interpolation)));
    }
  } else {
    c.draft.notes.push_back(fmt::format("{}: no geometryWarpFile: shown unwarped", fileset.path()));
  }
  const XmlAt alpha = fileset.child("alphaMap");
  if (alpha.present()) read_alpha(alpha, c, display, id, d);
  const XmlAt beta = fileset.child("betaMap");
  if (beta.present()) {
    check_depths(beta, c.draft);
    d.keys.push_back(archive_file(beta, c, display, id, "beta", "png", &d));
  }
  note_unused(fileset, {"geometryWarpFile", "alphaMap", "betaMap"}, c.draft);
}

// Every fileset by the region it names; a region named twice, or one no region has, refused.
std::map<std::string, XmlAt> filesets(const XmlAt& root, const std::vector<std::string>& ids) {
  std::map<std::string, XmlAt> out;
  for (const XmlAt& fs : root.child("files").children("fileset")) {
    const std::optional<std::string> region = fs.attribute("region");
    if (!region) fs.fail("region", "missing: a fileset names the region it is for");
    if (std::find(ids.begin(), ids.end(), *region) == ids.end())
      fs.fail("region", fmt::format("{}: no region of display has this id", quoted_value(*region)));
    if (!out.emplace(*region, fs).second)
      fs.fail("region", fmt::format("{}: a second fileset for this region", quoted_value(*region)));
  }
  return out;
}

struct Region {
  XmlAt at;
  std::string id;
};

// Every region of every buffer, placed; buffers side by side, left to right, in file order.
std::vector<Region> read_regions(const XmlAt& display, WallDraft& draft) {
  const std::vector<XmlAt> buffers = display.children("buffer");
  if (buffers.empty()) display.fail("buffer", "missing: the display has no buffer");
  long long count = 0;
  for (const XmlAt& b : buffers) count += static_cast<long long>(b.children("region").size());
  if (count > kMaxImportedDisplays) too_many_displays(display.file(), display.path(), count);
  if (buffers.size() > 1) {
    draft.notes.push_back(fmt::format(
        "{} buffers (pictures): placed side by side on one canvas, left to right", buffers.size()));
  }
  std::vector<Region> out;
  int left = 0;
  for (const XmlAt& b : buffers) {
    const int bw = b.integer_attribute("xResolution", 1, kMaxBufferSide);
    const int bh = b.integer_attribute("yResolution", 1, kMaxBufferSide);
    const std::string bid = b.attribute("id").value_or("");
    for (const XmlAt& r : b.children("region")) {
      const std::optional<std::string> id = r.attribute("id");
      if (!id || id->empty()) r.fail("id", "missing: a region has an id its fileset names");
      for (const Region& o : out) {
        if (o.id == *id)
          r.fail("id", fmt::format("{}: a second region of this id", quoted_value(*id)));
      }
      DraftDisplay d;
      d.width = r.integer_attribute("xResolution", 1, kMaxImportedSide);
      d.height = r.integer_attribute("yResolution", 1, kMaxImportedSide);
      const double x = r.number_attribute("x", 0, 1), y = r.number_attribute("y", 0, 1);
      const double w = r.number_attribute("xsize", 0, 1), h = r.number_attribute("ysize", 0, 1);
      d.x = left + static_cast<int>(std::lround(x * bw));
      d.y = static_cast<int>(std::lround(y * bh));
      d.origin = fmt::format("buffer {} region {}: x {} y {} xsize {} ysize {} of {}x{}",
                             quoted_value(bid), quoted_value(*id), x, y, w, h, bw, bh);
      if (std::abs(w * bw - d.width) > 1 || std::abs(h * bh - d.height) > 1) {
        draft.notes.push_back(fmt::format(
            "{}: covers {:.0f}x{:.0f} pixels of its buffer with a {}x{} raster: the wall shows "
            "it at its raster's size, one canvas pixel a projector pixel",
            r.path(), w * bw, h * bh, d.width, d.height));
      }
      note_unused(r, {}, draft);
      draft.displays.push_back(std::move(d));
      out.push_back({r, *id});
    }
    left += bw;
  }
  if (out.empty()) display.fail("buffer", "no region in any buffer: nothing to show");
  return out;
}

}  // namespace

ImportedWall import_mpcdi(std::string_view xml, const std::vector<std::string>& entries,
                          const std::filesystem::path& path, const MpcdiImport& options) {
  const std::string file = path.string();
  if (xml.size() > kMaxXmlBytes) {
    throw LayoutError(fmt::format("{}: {}: {} bytes, more than the {} it may have", file,
                                  kMpcdiXmlName, xml.size(), kMaxXmlBytes));
  }
  tinyxml2::XMLDocument doc;
  parse_mpcdi_xml(doc, xml, file);
  const tinyxml2::XMLElement* top = doc.RootElement();
  const XmlAt root(top, "MPCDI", file);
  if (!top || std::string_view(top->Name()) != "MPCDI") {
    root.fail("", fmt::format("the root element is {}: not an MPCDI document",
                              top ? quoted_value(top->Name()) : "missing"));
  }
  WallDraft draft;
  draft.name = path.stem().string();
  const std::string version = check_root(root, draft);
  draft.header = {
      fmt::format("Imported by tilelayout import from {} (MPCDI {}, the 2D media profile).", file,
                  version),
      "Each [[display]] is a region of the MPCDI display: x, y its place in its buffer (x, y "
      "times the buffer's resolution), width, height its xResolution, yResolution;",
      fmt::format("warp, alpha and beta the files its fileset names, extracted into {}/.",
                  options.maps_folder)};
  const std::vector<Region> regions = read_regions(root.child("display"), draft);
  std::vector<std::string> ids;
  for (const Region& r : regions) ids.push_back(r.id);
  const std::map<std::string, XmlAt> sets = filesets(root, ids);
  ImportedWall out;
  const Context c{entries, options, draft, out.files};
  for (std::size_t i = 0; i < regions.size(); ++i) {
    const auto fs = sets.find(regions[i].id);
    if (fs == sets.end()) {
      regions[i].at.fail("id", fmt::format("{}: no fileset in files names this region",
                                           quoted_value(regions[i].id)));
    }
    read_fileset(fs->second, c, static_cast<int>(i), regions[i].id, draft.displays[i]);
  }
  out.format = ImportFormat::Mpcdi;
  out.notes = draft.notes;
  out.display_count = static_cast<int>(draft.displays.size());
  out.toml = emit_wall(draft, file, out.hosts);
  return out;
}

}  // namespace l2
