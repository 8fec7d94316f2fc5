#include "svg_writer.hpp"

#include <algorithm>
#include <locale>
#include <sstream>

#include "granpipe/atomic_file.hpp"

namespace granpipe::arches {

namespace {

constexpr double kPixelWidth = 800.0;

struct Bounds {
  double x0, x1, y0, y1;
};

Bounds picture_bounds(const Frame& frame) {
  const Container& box = frame.container;
  const Eigen::Vector3d lo = box.lo + box.wall_offset, hi = box.hi + box.wall_offset;
  Bounds b{lo[0], hi[0], lo[1], lo[1]};
  if (box.boundary[1][1] != Boundary::Open) b.y1 = hi[1];
  double rmax = 0.0;
  for (Eigen::Index i = 0; i < frame.size(); ++i) {
    const double x = frame.position()(i, 0), y = frame.position()(i, 1), r = frame.radius()(i);
    b.x0 = std::min(b.x0, x - r);
    b.x1 = std::max(b.x1, x + r);
    b.y0 = std::min(b.y0, y - r);
    b.y1 = std::max(b.y1, y + r);
    rmax = std::max(rmax, r);
  }
  // A margin so that the walls' strokes are not cut off.
  const double margin = rmax > 0.0 ? rmax : 0.05 * (b.x1 - b.x0);
  return {b.x0 - margin, b.x1 + margin, b.y0 - margin, b.y1 + margin};
}

std::string wall_path(const Frame& frame, double top) {
  const Container& box = frame.container;
  const Eigen::Vector3d lo = box.lo + box.wall_offset, hi = box.hi + box.wall_offset;
  std::ostringstream d;
  d.imbue(std::locale::classic());
  if (box.boundary[0][0] == Boundary::Wall)
    d << "M " << lo[0] << ' ' << top << " L " << lo[0] << ' ' << lo[1] << ' ';
  if (box.boundary[1][0] == Boundary::Wall)
    d << "M " << lo[0] << ' ' << lo[1] << " L " << hi[0] << ' ' << lo[1] << ' ';
  if (box.boundary[0][1] == Boundary::Wall)
    d << "M " << hi[0] << ' ' << lo[1] << " L " << hi[0] << ' ' << top << ' ';
  if (box.boundary[1][1] == Boundary::Wall)
    d << "M " << lo[0] << ' ' << hi[1] << " L " << hi[0] << ' ' << hi[1] << ' ';
  return d.str();
}

std::string escape(const std::string& text) {
  std::string out;
  for (char c : text) {
    switch (c) {
      case '&':
        out += "&amp;";
        break;
      case '<':
        out += "&lt;";
        break;
      case '>':
        out += "&gt;";
        break;
      default:
        out += c;
    }
  }
  return out;
}

void write_circles(std::ostream& out, const Frame& frame, const std::vector<char>& in_arch,
                   char wanted) {
  for (Eigen::Index i = 0; i < frame.size(); ++i) {
    if (in_arch[static_cast<std::size_t>(i)] != wanted) continue;
    out << "<circle cx=\"" << frame.position()(i, 0) << "\" cy=\"" << frame.position()(i, 1)
        << "\" r=\"" << frame.radius()(i) << "\"/>\n";
  }
}

}  // namespace

void write_arches_svg(const std::filesystem::path& path, const Frame& frame,
                      const std::vector<Arch>& arches, const std::string& title,
                      const std::string& provenance) {
  const Bounds b = picture_bounds(frame);
  const double width = b.x1 - b.x0, height = b.y1 - b.y0;
  const double rmean = frame.size() > 0 ? frame.radius().mean() : 0.01 * width;
  std::vector<char> in_arch(static_cast<std::size_t>(frame.size()), 0);
  for (const Arch& a : arches)
    for (Eigen::Index d : a.disks) in_arch[static_cast<std::size_t>(d)] = 1;

  std::ostringstream out;
  out.imbue(std::locale::classic());
  out.precision(8);
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\" standalone=\"no\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" version=\"1.1\" width=\"" << kPixelWidth
      << "\" height=\"" << kPixelWidth * height / width << "\" viewBox=\"" << b.x0 << ' ' << -b.y1
      << ' ' << width << ' ' << height << "\">\n"
      << "<title>" << escape(title) << "</title>\n"
      << "<desc>" << escape(provenance)
      << "</desc>\n"
      // y points up in the packing and down in SVG.
      << "<g transform=\"scale(1,-1)\">\n"
      << "<path d=\"" << wall_path(frame, b.y1)
      << "\" fill=\"none\" stroke=\"black\" stroke-width=\"" << 0.2 * rmean << "\"/>\n"
      << "<g fill=\"#e0e0e0\" stroke=\"#606060\" stroke-width=\"" << 0.04 * rmean << "\">\n";
  write_circles(out, frame, in_arch, 0);
  out << "</g>\n<g fill=\"#f5c28a\" stroke=\"#606060\" stroke-width=\"" << 0.04 * rmean << "\">\n";
  write_circles(out, frame, in_arch, 1);
  out << "</g>\n<g stroke=\"#b00000\" stroke-width=\"" << 0.15 * rmean
      << "\" stroke-linecap=\"round\">\n";
  for (const Arch& a : arches) {
    for (std::size_t k = 0; k + 1 < a.disks.size(); ++k) {
      const Eigen::Index i = a.disks[k], j = a.disks[k + 1];
      const double x1 = frame.position()(i, 0), y1 = frame.position()(i, 1);
      const double x2 = x1 + frame.container.minimum_image(0, frame.position()(j, 0) - x1);
      out << "<line x1=\"" << x1 << "\" y1=\"" << y1 << "\" x2=\"" << x2 << "\" y2=\""
          << frame.position()(j, 1) << "\"/>\n";
    }
  }
  out << "</g>\n</g>\n</svg>\n";

  write_file_atomically(path, out.str());
}

}  // namespace granpipe::arches
