// load_scene / parse_scene: file -> text -> JSON -> overrides -> validated Scene.
#include "engine/scene/scene_loader.hpp"

#include <atomic>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>

#include "engine/core/errors.hpp"
#include "engine/scene/json_text.hpp"
#include "engine/scene/overrides.hpp"
#include "engine/scene/scene_json.hpp"

namespace vkw {
namespace {

[[noreturn]] void fail_open(const std::filesystem::path& file, int error) {
    throw UserError("cannot open scene file '" + file.string() + "': " + std::strerror(error));
}

// Whole file as bytes. C stdio rather than iostreams because errno then tells the reason
// ("No such file or directory", "Permission denied", "Is a directory").
std::string read_file(const std::filesystem::path& file) {
    errno = 0;
    const std::unique_ptr<std::FILE, int (*)(std::FILE*)> stream(std::fopen(file.c_str(), "rb"), &std::fclose);
    if (!stream) fail_open(file, errno);
    std::string text;
    char buffer[1 << 16];
    std::size_t count = 0;
    while ((count = std::fread(buffer, 1, sizeof buffer, stream.get())) > 0) text.append(buffer, count);
    if (std::ferror(stream.get())) fail_open(file, errno);
    return text;
}

}  // namespace

Scene parse_scene(std::string_view json_text, const std::filesystem::path& name_for_messages,
                  const std::vector<std::string>& overrides, const SceneLoadOptions& options) {
    ErrorContext errors(name_for_messages.string());
    nlohmann::json root = parse_json_text(json_text, errors);
    apply_overrides(root, overrides, errors);
    Scene scene =
        scene_from_json(root, errors, name_for_messages, FileScope(name_for_messages, options.allow_outside_paths));
    static std::atomic<uint64_t> loads{0};
    scene.load_id = ++loads;
    return scene;
}

Scene load_scene(const std::filesystem::path& file, const std::vector<std::string>& overrides,
                 const SceneLoadOptions& options) {
    return parse_scene(read_file(file), file, overrides, options);
}

}  // namespace vkw
