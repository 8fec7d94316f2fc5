#include "vtk_writer.hpp"

#include <cstdio>
#include <string>

#include "granpipe/atomic_file.hpp"
#include "granpipe/errors.hpp"
#include "vtk_polydata.hpp"

namespace granpipe::vtk {

std::string with_provenance(std::string xml, const std::string& provenance) {
  // A comment may not hold "--" (a pipeline named a--b).
  std::string said = provenance;
  for (std::size_t at = said.find("--"); at != std::string::npos; at = said.find("--", at))
    said.replace(at, 2, "- -");
  if (said.empty()) return xml;  // a writer made outside a run
  // The XML declaration must stay first.
  const std::size_t declaration_end = xml.find("?>\n");
  if (declaration_end == std::string::npos) throw InternalError("vtk: XML without a declaration");
  xml.insert(declaration_end + 3, "<!-- " + said + " -->\n");
  return xml;
}

VtkWriter::VtkWriter(const PluginContext& ctx)
    : files_(ctx.output_files()), provenance_(ctx.provenance) {}

void VtkWriter::write(const Frame& frame) {
  char number[24];
  std::snprintf(number, sizeof number, "_%06zu.vtp", written_.size());
  const std::filesystem::path file = files_.path(number);
  write_file_atomically(file, with_provenance(polydata_xml(frame), provenance_));
  written_.push_back({frame.time, frame.step, file.filename().string()});
}

void VtkWriter::close() {
  if (written_.empty()) return;  // no frame: no collection
  write_file_atomically(files_.path(".pvd"),
                        with_provenance(collection_xml(written_), provenance_));
}

}  // namespace granpipe::vtk
