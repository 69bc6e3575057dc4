#pragma once
/// What the isolated Gmsh reader process sends back to plisse: the reply of the child that opens
/// a `.msh` file with the Gmsh SDK (gmsh_io.cpp), as plain arrays copied from Gmsh's API, and its
/// wire format.
///
/// The child only copies; everything plisse decides (which element types it accepts, node
/// renumbering, duplicates, tags, orientation) is done by the parent on these arrays, so that it
/// runs in the process that sanitizers and the fuzzer watch.
///
/// Wire format (native byte order: both ends are the same executable), every field
/// length-prefixed:
///   "PLGM" u32:version u8:kind  payload  "END."
///   string  = u64:n_bytes bytes;   array<T> = u64:n_items n_items * sizeof(T) bytes
///   kind 1 (model):  u64:n_types {i32:type i32:dim string:name}
///                    array<u64>:node_tags array<f64>:coordinates
///                    u64:n_blocks {i32:type array<u64>:element_tags array<u64>:node_tags}
///                    u64:n_groups {i32:dim i32:tag string:name
///                                  u64:n {i32:type array<u64>:element_tags}}
///   kind 2 (error):  string:rule     (Gmsh's messages, or the exception's text)
///   kind 3 (out of memory): nothing
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace plisse {

// Gmsh element type numbers (Gmsh reference manual, "MSH file format", element types), which the
// reader and the writer share.
constexpr int kLine2 = 1, kTri3 = 2, kTet4 = 4, kTri6 = 9, kTet10 = 11, kPoint = 15;

class ChildOutput;

/// An element type found in the model (dimensions 2 and 3; also 1 for a shell's surface).
struct RawElementType {
  int type = 0;  ///< Gmsh element type number
  int dim = 0;
  std::string name;  ///< Gmsh's name, e.g. "Tetrahedron 4", for messages
};

/// All elements of one type in the model, in Gmsh's order.
struct RawElementBlock {
  int type = 0;
  std::vector<std::size_t> element_tags;
  std::vector<std::size_t> node_tags;  ///< nodes per element times element_tags.size()
};

/// Element tags of one type on the entities of a physical group.
struct RawGroupElements {
  int type = 0;
  std::vector<std::size_t> element_tags;
};

/// A physical group of dimension 2 or 3 (also 1 for a shell's surface).
struct RawPhysicalGroup {
  int dim = 0;
  int tag = 0;
  std::string name;  ///< empty when the file names none
  std::vector<RawGroupElements> elements;
};

/// The model as Gmsh's API gives it (getElementTypes, getNodes, getElementsByType,
/// getPhysicalGroups).
struct RawGmshModel {
  std::vector<RawElementType> types;
  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates;  ///< x, y, z per entry of node_tags
  std::vector<RawElementBlock> blocks;
  std::vector<RawPhysicalGroup> groups;
};

/// A decoded reply of the reader process.
struct GmshReaderReply {
  enum class Kind : std::uint8_t { model = 1, error = 2, out_of_memory = 3 };
  Kind kind = Kind::error;
  RawGmshModel model;  ///< kind == model
  std::string rule;    ///< kind == error
};

/// Writers (in the child).
void send_model(const RawGmshModel& model, ChildOutput& out);
void send_error(const std::string& rule, ChildOutput& out);
void send_out_of_memory(ChildOutput& out);

/// Decodes a reply. Returns false (and leaves `reply` unspecified) when the bytes are not one
/// complete, well-formed reply: a short message, a count larger than the bytes that follow, an
/// unknown kind, a missing end mark or bytes after it. Never allocates more than the message
/// size justifies.
bool decode_reply(std::span<const char> bytes, GmshReaderReply& reply);

}  // namespace plisse
