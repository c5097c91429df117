#include "tools/vkwater/view/parameter_panel.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace vkw::window {
namespace {

constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

// ImGui's widgets edit floats and ints; the scene holds doubles.
bool slider(const char* label, double& value, float lo, float hi, const char* format = "%.3f",
            ImGuiSliderFlags flags = 0) {
    float v = static_cast<float>(value);
    if (!ImGui::SliderFloat(label, &v, lo, hi, format, flags | ImGuiSliderFlags_AlwaysClamp)) return false;
    value = v;
    return true;
}

// Per-channel values >= 0 (irradiance, coefficients).
bool drag_rgb(const char* label, glm::dvec3& value, float speed) {
    float v[3] = {float(value.x), float(value.y), float(value.z)};
    if (!ImGui::DragFloat3(label, v, speed, 0.0f, 1000.0f, "%.4f", ImGuiSliderFlags_AlwaysClamp)) return false;
    value = {v[0], v[1], v[2]};
    return true;
}

const char* wave_model_name(WaveModel model) {
    switch (model) {
        case WaveModel::Flat: return "flat";
        case WaveModel::Sum: return "sum";
        case WaveModel::FftOcean: return "fft";
    }
    return "?";
}

// A power-of-two slider over [2^lo, 2^hi].
bool power_of_two(const char* label, uint32_t& value, int lo, int hi) {
    int exponent = std::clamp(static_cast<int>(std::lround(std::log2(std::max(value, 1u)))), lo, hi);
    const std::string shown = std::to_string(1u << exponent);
    if (!ImGui::SliderInt(label, &exponent, lo, hi, shown.c_str(), ImGuiSliderFlags_AlwaysClamp)) return false;
    value = 1u << exponent;
    return true;
}

}  // namespace

void ParameterPanel::reset(const Scene& scene) {
    base_waves_ = scene.water ? scene.water->waves : WaveSettings{};
    amplitude_scale_ = 1.0;
    wind_turn_deg_ = 0.0;
}

void ParameterPanel::apply_wave_edits(Water& water) const {
    WaveSettings& waves = water.waves;
    if (waves.model == WaveModel::Sum) {
        waves.components = base_waves_.components;
        for (WaveComponent& wave : waves.components) {
            wave.amplitude *= amplitude_scale_;
            // The file accepts directions in [-360, 360]: wrap the turned one into it.
            wave.direction_deg = std::remainder(wave.direction_deg + wind_turn_deg_, 360.0);
        }
    } else if (waves.model == WaveModel::FftOcean) {
        waves.ocean.amplitude_scale = base_waves_.ocean.amplitude_scale * amplitude_scale_;
    }
}

bool ParameterPanel::draw_sun(Scene& scene) {
    if (!ImGui::CollapsingHeader("Sun", ImGuiTreeNodeFlags_DefaultOpen)) return false;
    // The loader's convention (scenes/README.md): u toward the sun, the light travels along -u.
    const glm::dvec3 u = -scene.sun.direction;
    double elevation = std::asin(std::clamp(u.y, -1.0, 1.0)) / kDegToRad;
    double azimuth = std::atan2(u.x, -u.z) / kDegToRad;
    bool changed = slider("elevation (deg)", elevation, -90.0f, 90.0f, "%.1f");
    changed |= slider("azimuth (deg)", azimuth, -180.0f, 180.0f, "%.1f");
    if (changed) scene.sun.direction = -direction_toward_sun(elevation, azimuth);
    changed |= drag_rgb("irradiance (W/m^2)", scene.sun.irradiance, 0.01f);
    return changed;
}

bool ParameterPanel::draw_waves(Scene& scene) {
    if (!scene.water || !ImGui::CollapsingHeader("Water and waves", ImGuiTreeNodeFlags_DefaultOpen)) return false;
    Water& water = *scene.water;
    bool changed = slider("IOR", water.ior, 1.0f, 2.0f, "%.3f");
    // The models this scene can take: flat always, the FFT ocean with its defaults (or the
    // file's settings), a sum only when the file gave components.
    if (ImGui::BeginCombo("wave model", wave_model_name(water.waves.model))) {
        for (WaveModel model : {WaveModel::Flat, WaveModel::Sum, WaveModel::FftOcean}) {
            if (model == WaveModel::Sum && base_waves_.components.empty()) continue;
            if (ImGui::Selectable(wave_model_name(model), water.waves.model == model) && water.waves.model != model) {
                water.waves.model = model;
                apply_wave_edits(water);  // the new model takes the base waves, scaled and turned
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    bool edited = false;
    if (water.waves.model != WaveModel::Flat) {
        edited |= slider("amplitude scale", amplitude_scale_, 0.0f, 4.0f, "%.2f");
    }
    if (water.waves.model == WaveModel::Sum) {
        edited |= slider("wind turn (deg)", wind_turn_deg_, -180.0f, 180.0f, "%.1f");
    }
    if (water.waves.model == WaveModel::FftOcean) {
        FftOceanSettings& ocean = water.waves.ocean;
        changed |= slider("wind speed (m/s)", ocean.wind_speed, 0.5f, 30.0f, "%.1f");
        changed |= slider("wind direction (deg)", ocean.wind_direction_deg, -180.0f, 180.0f, "%.1f");
        changed |= slider("choppiness", ocean.choppiness, 0.0f, 2.0f, "%.2f");
    }
    if (edited) apply_wave_edits(water);
    return changed || edited;
}

bool ParameterPanel::draw_medium(Scene& scene) {
    if (!scene.water || !ImGui::CollapsingHeader("Medium", ImGuiTreeNodeFlags_DefaultOpen)) return false;
    Medium& medium = scene.medium;
    bool changed = false;
    const std::string current = medium.preset.empty() ? "custom" : medium.preset;
    if (ImGui::BeginCombo("preset", current.c_str())) {
        for (std::string_view name : medium_preset_names()) {
            if (ImGui::Selectable(std::string(name).c_str(), medium.preset == name)) {
                medium = *find_medium_preset(name);
                changed = true;
            }
        }
        ImGui::EndCombo();
    }
    bool coefficients = drag_rgb("sigma_a (1/m)", medium.sigma_a, 0.005f);
    coefficients |= drag_rgb("sigma_s (1/m)", medium.sigma_s, 0.005f);
    coefficients |= slider("g (Henyey-Greenstein)", medium.g, -0.99f, 0.99f, "%.2f");
    if (coefficients) medium.preset.clear();  // no longer the named water
    return changed || coefficients;
}

bool ParameterPanel::draw_effects(Scene& scene, const fg::FrameNeeds* needs) {
    if (!ImGui::CollapsingHeader("Effects", ImGuiTreeNodeFlags_DefaultOpen)) return false;
    static constexpr const char* kModes[] = {"auto", "on", "off"};
    bool changed = false;
    for (Effect effect : kAllEffects) {
        EffectSettings& settings = scene.effects[effect];
        int mode = static_cast<int>(settings.mode);
        ImGui::PushID(static_cast<int>(effect));
        ImGui::SetNextItemWidth(60.0f);
        if (ImGui::Combo(effect_name(effect), &mode, kModes, 3)) {
            settings.mode = static_cast<EffectMode>(mode);
            changed = true;
        }
        const fg::EffectDecision* decision = needs ? needs->find(effect) : nullptr;
        if (decision) {
            ImGui::SameLine();
            ImGui::TextColored(decision->needed ? ImVec4(0.5f, 1.0f, 0.5f, 1.0f) : ImVec4(1.0f, 0.6f, 0.4f, 1.0f), "%s",
                               decision->needed ? "runs" : "culled");
            if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", decision->reason.c_str());
        }
        ImGui::PopID();
    }
    return changed;
}

bool ParameterPanel::draw_quality(Scene& scene) {
    if (!ImGui::CollapsingHeader("Quality", ImGuiTreeNodeFlags_DefaultOpen)) return false;
    bool changed = false;
    if (scene.water) {
        changed |= power_of_two("water grid (cells per side)", scene.water->grid_resolution, 2, 12);
        if (scene.water->waves.model == WaveModel::FftOcean) {
            changed |= power_of_two("FFT grid", scene.water->waves.ocean.resolution, 4, 10);
        }
    }
    return changed;
}

namespace {
// A combo over the values 0 .. N-1 of an enum, named by `names`.
template <class Enum, std::size_t N>
bool enum_combo(const char* label, Enum& value, const char* const (&names)[N]) {
    int index = static_cast<int>(value);
    if (!ImGui::Combo(label, &index, names, static_cast<int>(N))) return false;
    value = static_cast<Enum>(index);
    return true;
}
}  // namespace

// The methods the published methods compare: the caustics' producer and splat, the surface's
// Fresnel form and Optical Phenomena c. 2008's depth colour, switched live to see what each changes.
bool ParameterPanel::draw_methods(Scene& scene) {
    if (!ImGui::CollapsingHeader("Methods")) return false;
    static constexpr const char* kMethods[] = {"photons", "procedural (Guardado & Sánchez-Crespo 2004)"};
    static constexpr const char* kKernels[] = {"bilinear", "adaptive", "footprint (Tipprasert 2006)"};
    static constexpr const char* kSplats[] = {"light-space map", "camera-space (Ojeda & Susín 2013)"};
    static constexpr const char* kFresnels[] = {"exact", "Schlick", "power term (Optical Phenomena c. 2008)"};
    CausticSettings& caustics = scene.effects.caustics;
    bool changed = enum_combo("caustics", caustics.method, kMethods);
    changed |= enum_combo("splat kernel", caustics.kernel, kKernels);
    changed |= enum_combo("splatted in", caustics.splat, kSplats);
    // Camera-space splats gather photons: the procedural method has none (the scene schema refuses it).
    if (caustics.splat == CausticSplat::CameraSpace && caustics.method != CausticMethod::Photons) {
        caustics.method = CausticMethod::Photons;
    }
    changed |= enum_combo("Fresnel", scene.effects.water.fresnel, kFresnels);
    bool blend = scene.effects.water.depth_blend.has_value();
    if (ImGui::Checkbox("depth colour (Optical Phenomena c. 2008)", &blend)) {
        scene.effects.water.depth_blend = blend ? std::optional<DepthBlend>(DepthBlend{}) : std::nullopt;
        changed = true;
    }
    return changed;
}

bool ParameterPanel::draw(Scene& scene, const fg::FrameNeeds* needs, ViewControls& controls) {
    ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360, 0), ImGuiCond_FirstUseEver);
    // Collapsed at first: open, the panel and the statistics covered most of an 800x600 window.
    ImGui::SetNextWindowCollapsed(true, ImGuiCond_FirstUseEver);
    ImGui::Begin("Scene (F1 hides)");
    ImGui::PushItemWidth(-150.0f);  // room for the labels right of the widgets
    bool changed = draw_sun(scene);
    changed |= draw_waves(scene);
    changed |= draw_medium(scene);
    changed |= draw_effects(scene, needs);
    changed |= draw_quality(scene);
    changed |= draw_methods(scene);
    if (ImGui::CollapsingHeader("Camera and time", ImGuiTreeNodeFlags_DefaultOpen)) {
        int mode = static_cast<int>(controls.camera_mode);
        ImGui::RadioButton("orbit", &mode, static_cast<int>(CameraMode::Orbit));
        ImGui::SameLine();
        ImGui::RadioButton("fly (Tab)", &mode, static_cast<int>(CameraMode::Fly));
        controls.camera_mode = static_cast<CameraMode>(mode);
        changed |= slider("field of view (deg)", scene.camera.fov_y_deg, 10.0f, 150.0f, "%.1f");
        changed |= slider("exposure", scene.camera.exposure, 0.01f, 100.0f, "%.3f", ImGuiSliderFlags_Logarithmic);
        ImGui::Checkbox("pause (Space)", &controls.paused);
        ImGui::SameLine();
        if (ImGui::Button("step (N)")) controls.step = true;
        slider("time speed", controls.time_speed, 0.0f, 4.0f, "%.2f");
        if (scene.water) ImGui::Text("water time: %.3f s", scene.water->time);
        ImGui::Checkbox("temporal accumulation", &controls.temporal);
        if (ImGui::Button("screenshot (F12)")) controls.screenshot = true;
        ImGui::SameLine();
        if (ImGui::Button("reload shaders (F5)")) controls.reload_shaders = true;
    }
    ImGui::PopItemWidth();
    ImGui::End();
    return changed;
}

}  // namespace vkw::window
