#include "xyz_writer.hpp"

#include <cstring>

namespace granpipe::xyz {

namespace {

// Extended XYZ names for the columns OVITO and ASE know; others keep their own name.
// Readers key the properties by name: a dump's column "pos" or "velo" written as such would
// be taken for the positions or velocities, so it gets "_column" added, as often as it takes
// to differ from the frame's other columns.
std::string xyz_name(const std::string& column, const PropertyTable& columns) {
  if (column == "position") return "pos";
  if (column == "velocity") return "velo";
  if (column != "pos" && column != "velo") return column;
  std::string name = column + "_column";
  while (columns.has(name)) name += "_column";
  return name;
}

char xyz_type(ValueType t) { return t == ValueType::Real ? 'R' : 'I'; }

void append_value(std::string& line, const Column& c, Eigen::Index i, int component, int digits) {
  char buf[40];
  std::visit(
      [&](const auto& a) {
        using A = std::decay_t<decltype(a)>;
        const auto v = A::ColsAtCompileTime == 1 ? a(i, 0) : a(i, component);
        if constexpr (std::is_same_v<typename A::Scalar, double>) {
          std::snprintf(buf, sizeof buf, "%.*g", digits, v);
        } else {
          std::snprintf(buf, sizeof buf, "%lld", static_cast<long long>(v));
        }
      },
      c.storage());
  line += ' ';
  line += buf;
}

}  // namespace

std::string comment_line(const Frame& f) {
  const Container& c = f.container;
  char buf[64];
  std::string lattice = "Lattice=\"";
  for (int a = 0; a < 3; ++a) {
    for (int b = 0; b < 3; ++b) {
      // A 2D frame gets a unit third axis, as OVITO expects a 3 x 3 cell.
      const double length = a < f.dim ? c.length(a) : 1.0;
      std::snprintf(buf, sizeof buf, "%s%.17g", a + b == 0 ? "" : " ", a == b ? length : 0.0);
      lattice += buf;
    }
  }
  // Without Origin viewers put the cell's corner at 0, off particles whose box starts elsewhere;
  // a vibrated container's walls are where they are at this frame, not at rest.
  std::string origin = "Origin=\"";
  for (int a = 0; a < 3; ++a) {
    std::snprintf(buf, sizeof buf, "%s%.17g", a ? " " : "", a < f.dim ? c.wall_at(a, 0) : 0.0);
    origin += buf;
  }
  std::string pbc = "pbc=\"";
  for (int a = 0; a < 3; ++a) {
    if (a) pbc += ' ';
    pbc += a < f.dim && c.periodic(a) ? 'T' : 'F';
  }
  std::string properties = "Properties=";
  for (std::size_t k = 0; k < f.particles.size(); ++k) {
    const Column& col = f.particles.column(k);
    if (k) properties += ':';
    properties += xyz_name(col.name(), f.particles);
    properties += ':';
    properties += xyz_type(col.property().type);
    properties += ':';
    properties += std::to_string(col.name() == "position" ? 3 : col.components());
  }
  std::snprintf(buf, sizeof buf, " Time=%.17g Step=%lld", f.time, static_cast<long long>(f.step));
  return lattice + "\" " + origin + "\" " + properties + " " + pbc + "\"" + buf;
}

std::string particle_line(const Frame& f, Eigen::Index i, int digits) {
  std::string line;
  for (std::size_t k = 0; k < f.particles.size(); ++k) {
    const Column& c = f.particles.column(k);
    // Positions always get three coordinates (z = 0 in 2D), as extended XYZ readers expect.
    const int components = c.name() == "position" ? 3 : c.components();
    for (int a = 0; a < components; ++a) {
      if (a < c.components()) {
        append_value(line, c, i, a, digits);
      } else {
        line += " 0";
      }
    }
  }
  return line.substr(1);
}

XyzWriter::XyzWriter(const PluginContext& ctx)
    : final_path_(ctx.output_files().path(".xyz")),
      partial_path_(ctx.output_files().path(".partial.xyz")),
      digits_(static_cast<int>(ctx.params.integer("digits"))),
      provenance_(ctx.provenance.empty() ? "" : " granpipe=\"" + ctx.provenance + "\"") {}

XyzWriter::~XyzWriter() {
  if (file_) std::fclose(file_);  // never closed: the run failed; .partial.xyz says so
}

void XyzWriter::write(const Frame& frame) {
  if (!file_) {
    file_ = std::fopen(partial_path_.c_str(), "wx");
    if (!file_) {
      throw InputError(partial_path_.string() + ": cannot create the file (" +
                       std::strerror(errno) + ")");
    }
  }
  std::string text = std::to_string(frame.size()) + "\n" + comment_line(frame) + provenance_ + "\n";
  for (Eigen::Index i = 0; i < frame.size(); ++i) text += particle_line(frame, i, digits_) + "\n";
  if (std::fwrite(text.data(), 1, text.size(), file_) != text.size() || std::fflush(file_) != 0) {
    throw InputError(partial_path_.string() + ": cannot write (is the disk full?)");
  }
}

void XyzWriter::close() {
  if (!file_) return;  // no frame: no file
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!closed) throw InputError(partial_path_.string() + ": cannot close (is the disk full?)");
  std::filesystem::rename(partial_path_, final_path_);
}

}  // namespace granpipe::xyz
