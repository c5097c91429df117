#include "tools/vkwater/view/view_script.hpp"

#include "engine/core/errors.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace vkw::window {
namespace {

constexpr std::string_view kForms =
    "FRAME: camera PX PY PZ TX TY TZ | move PX PY PZ TX TY TZ N | resize W H | set KEY=VALUE | "
    "screenshot PATH.exr | pause | resume | time SECONDS | mode orbit|fly | reload-shaders | wait-file PATH | heap";

struct VerbName {
    ScriptVerb verb;
    std::string_view name;
};
constexpr VerbName kVerbs[] = {{ScriptVerb::Camera, "camera"},
                               {ScriptVerb::Move, "move"},
                               {ScriptVerb::Resize, "resize"},
                               {ScriptVerb::Set, "set"},
                               {ScriptVerb::Screenshot, "screenshot"},
                               {ScriptVerb::Pause, "pause"},
                               {ScriptVerb::Resume, "resume"},
                               {ScriptVerb::Time, "time"},
                               {ScriptVerb::Mode, "mode"},
                               {ScriptVerb::ReloadShaders, "reload-shaders"},
                               {ScriptVerb::WaitFile, "wait-file"},
                               {ScriptVerb::Heap, "heap"}};

std::string_view trimmed(std::string_view text) {
    const size_t first = text.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    return text.substr(first, text.find_last_not_of(" \t\r") - first + 1);
}

std::vector<std::string_view> words(std::string_view text) {
    std::vector<std::string_view> out;
    size_t start = 0;
    while (true) {
        start = text.find_first_not_of(" \t", start);
        if (start == std::string_view::npos) return out;
        const size_t end = text.find_first_of(" \t", start);
        out.push_back(text.substr(start, end - start));
        if (end == std::string_view::npos) return out;
        start = end;
    }
}

// Throws with the file, the line and what was expected.
class LineErrors {
public:
    LineErrors(const std::string& file, int line) : file_(file), line_(line) {}
    [[noreturn]] void fail(const std::string& what, std::string_view accepted = kForms) const {
        throw UserError(file_ + ": line " + std::to_string(line_) + ": " + what +
                        " (accepted: " + std::string(accepted) + ")");
    }
    double number(std::string_view word, std::string_view what) const {
        double value = 0.0;
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (error != std::errc() || end != word.data() + word.size() || !std::isfinite(value)) {
            fail(std::string(what) + ": '" + std::string(word) + "' is not a finite number", "a finite number");
        }
        return value;
    }
    uint32_t count(std::string_view word, std::string_view what, uint32_t lo, uint32_t hi) const {
        uint32_t value = 0;
        const auto [end, error] = std::from_chars(word.data(), word.data() + word.size(), value);
        if (error != std::errc() || end != word.data() + word.size() || value < lo || value > hi) {
            fail(std::string(what) + ": '" + std::string(word) + "' is out of range",
                 "an integer " + std::to_string(lo) + " to " + std::to_string(hi));
        }
        return value;
    }

private:
    const std::string& file_;
    int line_;
};

void expect_arguments(const LineErrors& errors, const std::vector<std::string_view>& args, size_t count,
                      std::string_view form) {
    if (args.size() != count) {
        errors.fail(std::string(form.substr(0, form.find(' '))) + " takes " + std::to_string(count) + " argument" +
                        (count == 1 ? "" : "s") + ", got " + std::to_string(args.size()),
                    form);
    }
}

ScriptCommand parse_line(std::string_view line, const LineErrors& errors) {
    const size_t colon = line.find(':');
    if (colon == std::string_view::npos) errors.fail("no 'FRAME:' before the command");
    ScriptCommand command;
    command.frame = errors.count(trimmed(line.substr(0, colon)), "frame", 0, 100000000);
    const std::string_view rest = trimmed(line.substr(colon + 1));
    const std::vector<std::string_view> all = words(rest);
    if (all.empty()) errors.fail("no command after 'FRAME:'");
    const auto verb =
        std::find_if(std::begin(kVerbs), std::end(kVerbs), [&](const VerbName& v) { return v.name == all[0]; });
    if (verb == std::end(kVerbs)) errors.fail("unknown command '" + std::string(all[0]) + "'");
    command.verb = verb->verb;
    const std::vector<std::string_view> args(all.begin() + 1, all.end());
    auto pose = [&](glm::dvec3& position, glm::dvec3& target) {
        for (int i = 0; i < 3; ++i) position[i] = errors.number(args[i], "camera position");
        for (int i = 0; i < 3; ++i) target[i] = errors.number(args[3 + i], "camera target");
        if (glm::length(target - position) < 1e-6) {
            errors.fail("the target is the camera position", "a target at least 1e-6 m from the position");
        }
    };
    switch (command.verb) {
        case ScriptVerb::Camera:
            expect_arguments(errors, args, 6, "camera PX PY PZ TX TY TZ");
            pose(command.position, command.target);
            break;
        case ScriptVerb::Move:
            expect_arguments(errors, args, 7, "move PX PY PZ TX TY TZ N");
            pose(command.position, command.target);
            command.frames = errors.count(args[6], "move frames", 1, 100000000);
            break;
        case ScriptVerb::Resize:
            expect_arguments(errors, args, 2, "resize W H");
            command.width = errors.count(args[0], "resize width", 1, 16384);
            command.height = errors.count(args[1], "resize height", 1, 16384);
            break;
        case ScriptVerb::Set: {
            // The override is everything after "set": values may hold spaces ("description=a b").
            const std::string_view text = trimmed(rest.substr(all[0].size()));
            if (text.find('=') == std::string_view::npos) {
                errors.fail("set needs KEY=VALUE, got '" + std::string(text) + "'", "set KEY=VALUE, as --set takes it");
            }
            command.text = text;
            break;
        }
        case ScriptVerb::Screenshot: {
            expect_arguments(errors, args, 1, "screenshot PATH");
            // The screenshot is the EXR, its preview the same name with .png: a path of another
            // extension (or none) would get an EXR under a misleading name.
            std::string extension = std::filesystem::path(args[0]).extension().string();
            std::transform(extension.begin(), extension.end(), extension.begin(),
                           [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
            if (extension != ".exr") {
                errors.fail("screenshot '" + std::string(args[0]) + "' does not end in .exr",
                            "screenshot PATH.exr; the PNG preview is written beside it");
            }
            command.text = args[0];
            break;
        }
        case ScriptVerb::WaitFile:
            expect_arguments(errors, args, 1, "wait-file PATH");
            command.text = args[0];
            break;
        case ScriptVerb::Time:
            expect_arguments(errors, args, 1, "time SECONDS");
            command.seconds = errors.number(args[0], "time");
            break;
        case ScriptVerb::Mode:
            expect_arguments(errors, args, 1, "mode orbit|fly");
            if (args[0] != "orbit" && args[0] != "fly") {
                errors.fail("unknown camera mode '" + std::string(args[0]) + "'", "orbit, fly");
            }
            command.mode = args[0] == "fly" ? CameraMode::Fly : CameraMode::Orbit;
            break;
        case ScriptVerb::Pause:
        case ScriptVerb::Resume:
        case ScriptVerb::ReloadShaders:
        case ScriptVerb::Heap: expect_arguments(errors, args, 0, verb->name); break;
    }
    return command;
}

}  // namespace

const char* script_verb_name(ScriptVerb verb) {
    for (const VerbName& v : kVerbs) {
        if (v.verb == verb) return v.name.data();
    }
    return "?";
}

uint32_t ViewScript::frames_needed() const {
    uint32_t needed = 0;
    for (const ScriptCommand& command : commands) needed = std::max(needed, command.frame + command.frames + 1);
    return needed;
}

ViewScript parse_view_script(std::string_view text, const std::string& name_for_messages) {
    ViewScript script;
    script.name = name_for_messages;
    int number = 0;
    size_t start = 0;
    while (start <= text.size()) {
        const size_t end = std::min(text.find('\n', start), text.size());
        ++number;
        std::string_view line = text.substr(start, end - start);
        line = trimmed(line.substr(0, line.find('#')));
        if (!line.empty()) {
            ScriptCommand command = parse_line(line, LineErrors(name_for_messages, number));
            command.line = number;
            script.commands.push_back(std::move(command));
        }
        start = end + 1;
    }
    std::stable_sort(script.commands.begin(), script.commands.end(),
                     [](const ScriptCommand& a, const ScriptCommand& b) { return a.frame < b.frame; });
    return script;
}

ViewScript load_view_script(const std::filesystem::path& file) {
    std::ifstream stream(file, std::ios::binary);
    if (!stream || std::filesystem::is_directory(file)) {
        throw UserError("cannot read script '" + file.string() + "' (accepted: a text file of 'FRAME: COMMAND' lines)");
    }
    std::ostringstream text;
    text << stream.rdbuf();
    return parse_view_script(text.str(), file.string());
}

void check_script_fits(const ViewScript& script, uint32_t frames) {
    for (const ScriptCommand& command : script.commands) {
        if (command.frame + command.frames >= frames) {
            throw UserError(script.name + ": line " + std::to_string(command.line) + ": " +
                            script_verb_name(command.verb) + " at frame " + std::to_string(command.frame) +
                            (command.frames ? " (+" + std::to_string(command.frames) + " frames)" : "") +
                            " would not run within --frames " + std::to_string(frames) + " (accepted: frames 0 to " +
                            std::to_string(frames - 1) + ")");
        }
    }
}

}  // namespace vkw::window
