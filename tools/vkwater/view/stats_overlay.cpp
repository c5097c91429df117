#include "tools/vkwater/view/stats_overlay.hpp"

#include <imgui.h>

namespace vkw::window {

const char* const kViewerKeys =
    "left drag: turn (orbit: around the target)   right drag: pan (orbit)   wheel: zoom (orbit) / speed (fly)\n"
    "W A S D: move   Q E: down, up   Shift: 5x faster   Ctrl: 5x slower   Tab: orbit / fly\n"
    "Space: pause time   N: step a frame   F12: screenshot (EXR + PNG)   F5: reload shaders\n"
    "F1: hide panels   Esc: quit";

namespace {
constexpr float kWidth = 330.0f;
}  // namespace

void draw_stats_overlay(const OverlayInfo& info) {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - 10.0f, viewport->WorkPos.y + 10.0f),
                            ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowBgAlpha(0.6f);
    // A fixed width, wrapped text: the panel on the left keeps its room on an 800-pixel window.
    ImGui::SetNextWindowSize(ImVec2(kWidth, 0.0f), ImGuiCond_Always);
    const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoMove;
    ImGui::Begin("Statistics", nullptr, flags);
    const double frame_ms = info.stats->recent_frame_ms();
    if (frame_ms > 0.0) {
        ImGui::Text("frame %.1f ms (%.1f fps)", frame_ms, 1000.0 / frame_ms);
    } else {
        ImGui::Text("frame: warming up");
    }
    ImGui::TextWrapped("%ux%u, present %s, %s; device frames made %zu times", info.extent.width, info.extent.height,
                       info.present_mode.c_str(), info.device.c_str(), info.realize_count);
    ImGui::TextWrapped("camera (%s) at %.2f %.2f %.2f, %s the mean water level%s", camera_mode_name(info.camera_mode),
                       info.camera_position.x, info.camera_position.y, info.camera_position.z,
                       info.camera_in_water ? "below" : "above", info.paused ? "; time paused" : "");
    if (info.photons > 0) {
        ImGui::TextWrapped("caustic photons: %llu (one per cell of the %ux%u surface grid)",
                           static_cast<unsigned long long>(info.photons), info.photon_grid, info.photon_grid);
    } else {
        ImGui::TextUnformatted("caustic photons: none (caustics culled)");
    }
    for (const std::string& line : info.budget) ImGui::TextWrapped("%s", line.c_str());
    if (!info.message.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.5f, 0.4f, 1.0f));
        ImGui::TextWrapped("%s", info.message.c_str());
        ImGui::PopStyleColor();
    }

    // The pass table is closed until asked for: open, it covered most of an 800x600 window.
    if (info.stats->has_timing() && ImGui::CollapsingHeader("pass times")) {
        const fg::FrameReport& report = info.stats->last_report();
        ImGui::TextWrapped(
            "pass times of frame %llu (%s):", static_cast<unsigned long long>(info.stats->last_timing_frame()),
            report.method_name().c_str());
        if (ImGui::BeginTable("passes", 2, ImGuiTableFlags_SizingFixedFit)) {
            for (const fg::PassTime& pass : report.passes) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(pass.pass.c_str());
                ImGui::TableNextColumn();
                ImGui::Text("%8.2f ms", pass.ms);
            }
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextUnformatted("present (tonemap + overlay)");
            ImGui::TableNextColumn();
            ImGui::Text("%8.2f ms", info.stats->last_present_ms());
            ImGui::EndTable();
        }
    }
    if (info.graph && ImGui::CollapsingHeader("frame graph")) {
        const fg::CompiledGraph& compiled = info.graph->compiled();
        for (uint32_t pass : compiled.order) ImGui::BulletText("%s", info.graph->passes()[pass].name.c_str());
        for (const fg::CulledPass& culled : compiled.culled) {
            ImGui::TextDisabled("culled: %s (%s)", culled.name.c_str(), culled.reason.c_str());
        }
    }
    if (ImGui::CollapsingHeader("keys")) ImGui::TextWrapped("%s", kViewerKeys);
    ImGui::End();
}

}  // namespace vkw::window
