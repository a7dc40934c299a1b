#include "scene/gltf/TinygltfModel.h"

#include "core/TextFile.h"
#include "core/Error.h"
#include "core/Text.h"
#include "scene/gltf/Problems.h"

#include <climits>
#include <regex>
#include <exception>
#include <vector>

namespace lenslab::gltf {
namespace fs = std::filesystem;

namespace {

// tinygltf 2.7 decodes every image while it parses, used or not, and hands the callback for an
// image in a bufferView a pointer that it never checked against the buffer. This one keeps the
// encoded bytes of uri images only: bufferView images are read later from a checked view, and
// only the images the drawn scene samples are decoded (decodeImage).
// tinygltf-2.7: this callback ignores the bufferView pointer that tinygltf 2.7 passes unchecked; that
// part can go when tinygltf is upgraded to one that checks it (decoding only the images the scene
// uses is lenslab's own choice and stays).
bool keepEncodedImage(tinygltf::Image* image, const int, std::string*, std::string*, int, int,
                      const unsigned char* bytes, int size, void*) {
  if (image->bufferView < 0 && bytes != nullptr && size > 0) image->image.assign(bytes, bytes + size);
  return true;
}

// External files (.bin buffers, images) read as the scene file is: a regular file, at most 4 GiB,
// so that a uri naming /dev/zero or a FIFO is refused instead of read until memory runs out.
// `filesRead` (the callbacks' user data) collects the files read, for Scene::files.
bool readWholeInputFile(std::vector<unsigned char>* out, std::string* error, const std::string& file, void* filesRead) {
  try {
    const std::string bytes = readInputFile(file, "file a uri names", kMaxGltfFileBytes);
    out->assign(bytes.begin(), bytes.end());
    static_cast<std::vector<fs::path>*>(filesRead)->push_back(file);
    return true;
  } catch (const InputError& e) {
    if (error) *error += e.what();
    return false;
  }
}

// tinygltf's messages that a user cannot act on as they stand, in lenslab's words.
std::string inOurWords(const std::string& reason) {
  static const std::regex sizeMismatch(R"(File size mismatch : (.*), requestedBytes (\d+), but got (\d+))");
  std::smatch m;
  if (std::regex_search(reason, m, sizeMismatch))
    return cat("buffer file ", m[1].str(), " holds ", m[3].str(), " bytes, but its buffer's byteLength says ",
               m[2].str(), "; give the file's own length as byteLength");
  return reason;
}

}  // namespace

tinygltf::Model parseModel(std::string_view input, bool binary, const fs::path& directory,
                           std::vector<fs::path>& filesRead) {
  if (input.size() > UINT_MAX) refuse("the file is larger than the 4 GiB that glTF allows");
  tinygltf::TinyGLTF gltf;
  gltf.SetImageLoader(&keepEncodedImage, nullptr);
  gltf.SetFsCallbacks(
      {&tinygltf::FileExists, &tinygltf::ExpandFilePath, &readWholeInputFile, &tinygltf::WriteWholeFile, &filesRead});
  tinygltf::Model model;
  std::string error, warning;
  bool ok = false;
  const auto size = static_cast<unsigned int>(input.size());
  try {
    ok = binary
             ? gltf.LoadBinaryFromMemory(&model, &error, &warning, reinterpret_cast<const unsigned char*>(input.data()),
                                         size, directory.string())
             : gltf.LoadASCIIFromString(&model, &error, &warning, input.data(), size, directory.string());
  } catch (const std::exception& e) {
    refuse("tinygltf failed: ", e.what());
  }
  if (!ok) {
    // tinygltf 2.7 puts some reasons for failing (an empty image file) in the warnings only.
    // tinygltf-2.7: the reason is taken from the warnings when the error is empty; can go when
    // tinygltf is upgraded to one that puts every reason for failing in the error.
    const std::string reason = oneLine(error.empty() ? warning : error);
    refuse(reason.empty() ? std::string("tinygltf could not read it") : inOurWords(reason));
  }
  return model;
}

// A bufferView's bytes, after checking that it lies inside its buffer.
// tinygltf-2.7: bufferView ranges are checked here because tinygltf 2.7 checks none; can go when
// tinygltf is upgraded to one that refuses a bufferView past its buffer (verify that it does).
Bytes viewBytes(const tinygltf::Model& model, int viewIndex, const std::string& what) {
  requireIndex(viewIndex, model.bufferViews.size(), what, "bufferView");
  const tinygltf::BufferView& view = model.bufferViews[toIndex(viewIndex)];
  requireIndex(view.buffer, model.buffers.size(), cat("bufferView ", viewIndex), "buffer");
  const std::vector<unsigned char>& data = model.buffers[toIndex(view.buffer)].data;
  if (view.byteOffset > data.size() || view.byteLength > data.size() - view.byteOffset)
    refuse("bufferView ", viewIndex, " (byteOffset ", view.byteOffset, ", byteLength ", view.byteLength,
           ") runs past the end of buffer ", view.buffer, " (", data.size(), " bytes)");
  return Bytes(data).subspan(view.byteOffset, view.byteLength);
}

}  // namespace lenslab::gltf
