// The course's binary geometry files (hw6/sponza.xml: <VertexData>, <TexCoordData> and
// <Faces> with a binaryFile attribute instead of inline text). Their layout, from
// hw6/SPEC.txt (section 4, hint 4) and confirmed by two public CENG795 renderers that read
// them the same way: a 4-byte signed count N (vertices, texture coordinates, or faces),
// then N records of 4-byte values with no other header or padding: x y z floats per
// vertex, u v floats per texture coordinate, three int vertex indices per face.
// Little-endian, as the x86 machines that wrote them store words.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace rt {
namespace loader {

// The N * per_record values of `path`, as raw 32-bit words in file order. Throws
// rt::InputError with one line naming the file and what is wrong: it cannot be opened, it
// is shorter than its count says (truncated), longer (a count mismatch), or its count is
// negative.
std::vector<uint32_t> read_binary_records(const std::string& path, int per_record);

// The words reinterpreted: IEEE-754 floats, or two's-complement ints.
std::vector<float> words_as_floats(const std::vector<uint32_t>& words);
std::vector<int32_t> words_as_ints(const std::vector<uint32_t>& words);

}  // namespace loader
}  // namespace rt
