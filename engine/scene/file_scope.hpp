// Where the files a scene names may be. By default a scene reads only inside its own file's folder
// tree: a glTF receiver, the buffers and images that glTF names. A scene downloaded from anywhere
// then cannot make vkwater read /etc/passwd through a buffer URI of "../../etc/passwd". The CLI's
// --allow-outside-paths lifts the rule for scenes the user trusts.
#pragma once

#include <filesystem>
#include <string>

namespace vkw {

class FileScope {
public:
    // `scene_file` is the scene's own path (or the name that stands in for it); its folder is the
    // root of the allowed tree.
    FileScope(const std::filesystem::path& scene_file, bool allow_outside);

    // The folder relative names in the scene file are resolved against.
    const std::filesystem::path& scene_folder() const { return scene_folder_; }

    // `name` (a path relative to `from_folder` unless absolute), checked. `what` says who named
    // it ("buffers[0].uri"), and the message quotes `written_as` (the name as the file spells it,
    // when `name` is a decoded form of it). Throws vkw::UserError in one line when the name
    // resolves outside the scene's folder tree (symbolic links followed) and outside files are not
    // allowed.
    std::filesystem::path resolve(const std::filesystem::path& from_folder, const std::string& name,
                                  const std::string& what, const std::string& written_as = {}) const;

private:
    std::filesystem::path scene_folder_;
    bool allow_outside_;
};

// A URI's %XX escapes decoded (glTF URIs are URI-encoded; tinygltf decodes them before opening
// the file, so the check must see the same name). A malformed escape is kept as written.
std::string decode_uri_escapes(const std::string& uri);

}  // namespace vkw
