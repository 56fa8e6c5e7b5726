// Independent checks of the report files, shared by the report tests: plan.svg through libxml2 (a real XML
// parser, tests only), scene.glb through a structural reading of the GLB container and its glTF JSON.
#pragma once
#include <libxml/parser.h>
#include <libxml/tree.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace roomsense::test {

inline std::vector<std::uint8_t> read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::vector<std::uint8_t>(std::istreambuf_iterator<char>(in), {});
}

// ---- plan.svg ------------------------------------------------------------------------------------------

struct SvgArea {
  std::string index, type, size, reach, fill, points, title;
};

struct SvgReading {
  bool well_formed = false;
  std::string error;
  std::string root;                      // the root element's name
  std::map<std::string, std::string> ids;  // id -> element name
  std::map<std::string, std::string> path_data;  // id -> d, for <path id=...>
  std::vector<SvgArea> areas;            // every element with class="area", in document order
};

inline std::string xml_attr(xmlNode* node, const char* name) {
  xmlChar* v = xmlGetProp(node, reinterpret_cast<const xmlChar*>(name));
  if (v == nullptr) return {};
  std::string s(reinterpret_cast<const char*>(v));
  xmlFree(v);
  return s;
}

inline void walk_svg(xmlNode* node, SvgReading& r) {
  for (xmlNode* n = node; n != nullptr; n = n->next) {
    if (n->type != XML_ELEMENT_NODE) continue;
    const std::string name(reinterpret_cast<const char*>(n->name));
    const std::string id = xml_attr(n, "id");
    if (!id.empty()) r.ids[id] = name;
    if (!id.empty() && name == "path") r.path_data[id] = xml_attr(n, "d");
    if (xml_attr(n, "class") == "area") {
      SvgArea a{xml_attr(n, "data-index"), xml_attr(n, "data-type"), xml_attr(n, "data-size"),
                xml_attr(n, "data-reach"), xml_attr(n, "fill"), xml_attr(n, "points"), {}};
      for (xmlNode* c = n->children; c != nullptr; c = c->next)
        if (c->type == XML_ELEMENT_NODE && std::strcmp(reinterpret_cast<const char*>(c->name), "title") == 0) {
          xmlChar* t = xmlNodeGetContent(c);
          if (t != nullptr) {
            a.title = reinterpret_cast<const char*>(t);
            xmlFree(t);
          }
        }
      r.areas.push_back(a);
    }
    walk_svg(n->children, r);
  }
}

inline SvgReading read_svg(const std::string& text) {
  SvgReading r;
  xmlDoc* doc = xmlReadMemory(text.data(), int(text.size()), "plan.svg", nullptr, XML_PARSE_NONET | XML_PARSE_NOWARNING);
  if (doc == nullptr) {
    const xmlError* e = xmlGetLastError();
    r.error = e != nullptr && e->message != nullptr ? e->message : "not well-formed";
    return r;
  }
  r.well_formed = true;
  xmlNode* root = xmlDocGetRootElement(doc);
  if (root != nullptr) {
    r.root = reinterpret_cast<const char*>(root->name);
    walk_svg(root, r);
  }
  xmlFreeDoc(doc);
  return r;
}

// Which channel of "#rrggbb" is strongest: 'r', 'g' or 'b' ('?' when unreadable or tied).
inline char dominant_channel(const std::string& hex) {
  if (hex.size() != 7 || hex[0] != '#') return '?';
  int c[3];
  for (int i = 0; i < 3; ++i) c[i] = std::stoi(hex.substr(std::size_t(1 + 2 * i), 2), nullptr, 16);
  if (c[0] > c[1] && c[0] > c[2]) return 'r';
  if (c[1] > c[0] && c[1] > c[2]) return 'g';
  if (c[2] > c[0] && c[2] > c[1]) return 'b';
  return '?';
}

inline char expected_channel(const std::string& reach) {
  return reach == "close" ? 'r' : reach == "distance" ? 'g' : reach == "none" ? 'b' : '?';
}

// ---- scene.glb -----------------------------------------------------------------------------------------

struct GlbReading {
  std::vector<std::string> problems;  // empty when the file passes
  nlohmann::json doc;
  std::vector<std::string> node_names;  // of the scene's nodes, in order
};

inline std::uint32_t glb_u32(const std::vector<std::uint8_t>& b, std::size_t at) {
  std::uint32_t v = 0;
  if (at + 4 <= b.size()) std::memcpy(&v, b.data() + at, 4);
  return v;
}

// The GLB container (header, JSON chunk, BIN chunk, 4-byte padding) and the glTF objects that index into
// it: buffers, bufferViews, accessors (bounds, alignment, POSITION min/max, index values), meshes, nodes.
inline GlbReading check_glb(const std::vector<std::uint8_t>& b) {
  GlbReading r;
  auto& P = r.problems;
  if (b.size() < 20) {
    P.push_back("shorter than a header and a chunk header");
    return r;
  }
  if (glb_u32(b, 0) != 0x46546C67u) P.push_back("magic is not 'glTF'");
  if (glb_u32(b, 4) != 2) P.push_back("version is not 2");
  if (glb_u32(b, 8) != b.size()) P.push_back("header length " + std::to_string(glb_u32(b, 8)) + " != file size " + std::to_string(b.size()));
  const std::size_t json_len = glb_u32(b, 12);
  if (glb_u32(b, 16) != 0x4E4F534Au) P.push_back("first chunk is not JSON");
  if (json_len % 4 != 0) P.push_back("JSON chunk length not a multiple of 4");
  if (20 + json_len > b.size()) {
    P.push_back("JSON chunk runs past the file");
    return r;
  }
  const std::string text(b.begin() + 20, b.begin() + 20 + std::ptrdiff_t(json_len));
  // Padding of the JSON chunk must be spaces (0x20).
  const std::size_t last = text.find_last_not_of(' ');
  if (last == std::string::npos || text.size() - last - 1 > 3) P.push_back("JSON chunk padding is not 0-3 spaces");
  try {
    r.doc = nlohmann::json::parse(text);
  } catch (const std::exception& e) {
    P.push_back(std::string("JSON does not parse: ") + e.what());
    return r;
  }
  const nlohmann::json& d = r.doc;
  std::size_t bin_len = 0;
  const std::size_t bin_at = 20 + json_len;
  const std::uint8_t* bin = nullptr;
  if (bin_at < b.size()) {
    if (bin_at + 8 > b.size()) {
      P.push_back("truncated BIN chunk header");
      return r;
    }
    bin_len = glb_u32(b, bin_at);
    if (glb_u32(b, bin_at + 4) != 0x004E4942u) P.push_back("second chunk is not BIN");
    if (bin_len % 4 != 0) P.push_back("BIN chunk length not a multiple of 4");
    if (bin_at + 8 + bin_len != b.size()) P.push_back("BIN chunk does not end the file");
    if (bin_at + 8 + bin_len > b.size()) return r;
    bin = b.data() + bin_at + 8;
  }
  if (!d.contains("asset") || d["asset"].value("version", "") != "2.0") P.push_back("asset.version is not 2.0");

  std::size_t buffer_len = 0;
  if (d.contains("buffers")) {
    if (d["buffers"].size() != 1) P.push_back("expected exactly one buffer");
    buffer_len = d["buffers"][0].value("byteLength", std::size_t(0));
    if (d["buffers"][0].contains("uri")) P.push_back("GLB buffer 0 must not have a uri");
    if (bin == nullptr) P.push_back("buffers but no BIN chunk");
    if (buffer_len > bin_len || bin_len - buffer_len > 3) P.push_back("buffer byteLength does not match the BIN chunk");
  }
  const nlohmann::json views = d.value("bufferViews", nlohmann::json::array());
  for (std::size_t i = 0; i < views.size(); ++i) {
    const auto& v = views[i];
    const std::size_t off = v.value("byteOffset", std::size_t(0)), len = v.value("byteLength", std::size_t(0));
    if (v.value("buffer", -1) != 0) P.push_back("bufferView " + std::to_string(i) + " not in buffer 0");
    if (len == 0 || off + len > buffer_len) P.push_back("bufferView " + std::to_string(i) + " outside the buffer");
    if (off % 4 != 0) P.push_back("bufferView " + std::to_string(i) + " not 4-byte aligned");
  }
  const auto component_size = [](int type) -> std::size_t {
    switch (type) {
      case 5120: case 5121: return 1;
      case 5122: case 5123: return 2;
      case 5125: case 5126: return 4;
      default: return 0;
    }
  };
  const auto component_count = [](const std::string& type) -> std::size_t {
    if (type == "SCALAR") return 1;
    if (type == "VEC2") return 2;
    if (type == "VEC3") return 3;
    if (type == "VEC4" || type == "MAT2") return 4;
    if (type == "MAT3") return 9;
    if (type == "MAT4") return 16;
    return 0;
  };
  const nlohmann::json accessors = d.value("accessors", nlohmann::json::array());
  // Where each accessor's data lies, for the value checks below (nullopt when out of bounds).
  struct Span {
    const std::uint8_t* data;
    std::size_t count, stride, elem;
    int component_type;
  };
  std::vector<std::optional<Span>> spans(accessors.size());
  for (std::size_t i = 0; i < accessors.size(); ++i) {
    const auto& a = accessors[i];
    const std::string name = "accessor " + std::to_string(i);
    const int view = a.value("bufferView", -1);
    const std::size_t csize = component_size(a.value("componentType", 0)), ccount = component_count(a.value("type", ""));
    const std::size_t count = a.value("count", std::size_t(0)), off = a.value("byteOffset", std::size_t(0));
    if (csize == 0 || ccount == 0) {
      P.push_back(name + ": bad componentType or type");
      continue;
    }
    if (count == 0) P.push_back(name + ": count 0");
    if (view < 0 || std::size_t(view) >= views.size()) {
      P.push_back(name + ": bad bufferView");
      continue;
    }
    const auto& v = views[std::size_t(view)];
    const std::size_t elem = csize * ccount, stride = v.value("byteStride", elem);
    const std::size_t view_off = v.value("byteOffset", std::size_t(0)), view_len = v.value("byteLength", std::size_t(0));
    if (off + count * stride > view_len || stride < elem) P.push_back(name + ": runs past its bufferView");
    else if ((view_off + off) % csize != 0) P.push_back(name + ": not aligned to its component size");
    else if (bin != nullptr && view_off + view_len <= buffer_len)
      spans[i] = Span{bin + view_off + off, count, stride, elem, a.value("componentType", 0)};
  }
  const auto read_index = [](const Span& s, std::size_t k) -> std::uint32_t {
    const std::uint8_t* p = s.data + k * s.stride;
    if (s.component_type == 5121) return *p;
    if (s.component_type == 5123) {
      std::uint16_t v;
      std::memcpy(&v, p, 2);
      return v;
    }
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
  };
  const nlohmann::json meshes = d.value("meshes", nlohmann::json::array());
  for (std::size_t m = 0; m < meshes.size(); ++m)
    for (const auto& prim : meshes[m].value("primitives", nlohmann::json::array())) {
      const std::string name = "mesh " + std::to_string(m);
      const int pos = prim.contains("attributes") ? prim["attributes"].value("POSITION", -1) : -1;
      if (pos < 0 || std::size_t(pos) >= accessors.size() || !spans[std::size_t(pos)]) {
        P.push_back(name + ": no readable POSITION accessor");
        continue;
      }
      const auto& pa = accessors[std::size_t(pos)];
      const Span& ps = *spans[std::size_t(pos)];
      if (pa.value("type", "") != "VEC3" || pa.value("componentType", 0) != 5126) P.push_back(name + ": POSITION not float VEC3");
      if (!pa.contains("min") || !pa.contains("max")) P.push_back(name + ": POSITION without min/max");
      else {
        float lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
        for (std::size_t k = 0; k < ps.count; ++k) {
          float v[3];
          std::memcpy(v, ps.data + k * ps.stride, 12);
          for (int c = 0; c < 3; ++c) {
            if (!std::isfinite(v[c])) P.push_back(name + ": non-finite position");
            lo[c] = std::min(lo[c], v[c]);
            hi[c] = std::max(hi[c], v[c]);
          }
        }
        for (int c = 0; c < 3; ++c)
          if (pa["min"][std::size_t(c)].get<float>() != lo[c] || pa["max"][std::size_t(c)].get<float>() != hi[c])
            P.push_back(name + ": POSITION min/max differ from the data");
      }
      if (prim.contains("indices")) {
        const int ia = prim["indices"].get<int>();
        if (ia < 0 || std::size_t(ia) >= accessors.size() || !spans[std::size_t(ia)]) {
          P.push_back(name + ": unreadable indices");
          continue;
        }
        const auto& acc = accessors[std::size_t(ia)];
        const int ct = acc.value("componentType", 0);
        if (acc.value("type", "") != "SCALAR" || (ct != 5121 && ct != 5123 && ct != 5125))
          P.push_back(name + ": indices not unsigned SCALAR");
        const Span& is = *spans[std::size_t(ia)];
        if (prim.value("mode", 4) == 4 && is.count % 3 != 0) P.push_back(name + ": index count not a multiple of 3");
        for (std::size_t k = 0; k < is.count; ++k)
          if (read_index(is, k) >= ps.count) {
            P.push_back(name + ": index " + std::to_string(read_index(is, k)) + " >= vertex count " + std::to_string(ps.count));
            break;
          }
      }
      if (prim.contains("material")) {
        const int mat = prim["material"].get<int>();
        if (mat < 0 || std::size_t(mat) >= d.value("materials", nlohmann::json::array()).size())
          P.push_back(name + ": bad material");
      }
    }
  const nlohmann::json nodes = d.value("nodes", nlohmann::json::array());
  for (std::size_t n = 0; n < nodes.size(); ++n)
    if (nodes[n].contains("mesh") && nodes[n]["mesh"].get<std::size_t>() >= meshes.size())
      P.push_back("node " + std::to_string(n) + ": bad mesh");
  const std::size_t scene = d.value("scene", std::size_t(0));
  if (!d.contains("scenes") || scene >= d["scenes"].size()) P.push_back("no default scene");
  else
    for (const auto& n : d["scenes"][scene].value("nodes", nlohmann::json::array())) {
      const std::size_t i = n.get<std::size_t>();
      if (i >= nodes.size()) P.push_back("scene names a missing node");
      else r.node_names.push_back(nodes[i].value("name", ""));
    }
  return r;
}

}  // namespace roomsense::test
