#include "engine/window/imgui_layer.hpp"

#include "engine/core/errors.hpp"
#include "engine/vk/check.hpp"
#include "engine/vk/context.hpp"

#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>
#include <imgui.h>

namespace vkw::window {
namespace {

void check_imgui_vk_result(VkResult result) { VKW_CHECK(result, "Dear ImGui's Vulkan backend"); }

}  // namespace

ImGuiLayer::ImGuiLayer(Context& context, GLFWwindow* window, uint32_t frames_in_flight)
    : context_(context), frames_in_flight_(frames_in_flight) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // no imgui.ini in the user's working directory
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForVulkan(window, true);

    // The font atlas is ImGui's only descriptor set; a few spare for a reconnect.
    const VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 4};
    VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
    info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
    info.maxSets = 4;
    info.poolSizeCount = 1;
    info.pPoolSizes = &size;
    VKW_CHECK(vkCreateDescriptorPool(context_.device(), &info, nullptr, &pool_), "Dear ImGui descriptor pool");
    context_.set_name(pool_, VK_OBJECT_TYPE_DESCRIPTOR_POOL, "Dear ImGui descriptor pool");
}

ImGuiLayer::~ImGuiLayer() {
    vkDeviceWaitIdle(context_.device());
    disconnect();
    vkDestroyDescriptorPool(context_.device(), pool_, nullptr);
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
}

void ImGuiLayer::disconnect() {
    if (format_ == VK_FORMAT_UNDEFINED) return;
    ImGui_ImplVulkan_Shutdown();
    format_ = VK_FORMAT_UNDEFINED;
}

void ImGuiLayer::connect(VkRenderPass render_pass, VkFormat format) {
    vkDeviceWaitIdle(context_.device());
    disconnect();
    ImGui_ImplVulkan_InitInfo info{};
    info.Instance = context_.instance();
    info.PhysicalDevice = context_.physical_device();
    info.Device = context_.device();
    info.QueueFamily = context_.queue_family();
    info.Queue = context_.queue();
    info.DescriptorPool = pool_;
    info.Subpass = 0;
    info.MinImageCount = 2;
    info.ImageCount = frames_in_flight_;
    info.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    info.CheckVkResultFn = check_imgui_vk_result;
    if (!ImGui_ImplVulkan_Init(&info, render_pass)) throw InternalError("Dear ImGui's Vulkan backend failed to start");
    format_ = format;
    context_.submit_and_wait([](VkCommandBuffer cmd) { ImGui_ImplVulkan_CreateFontsTexture(cmd); },
                             "Dear ImGui font upload");
    ImGui_ImplVulkan_DestroyFontUploadObjects();
}

void ImGuiLayer::new_frame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::finish_frame() { ImGui::Render(); }

void ImGuiLayer::record(VkCommandBuffer cmd) const { ImGui_ImplVulkan_RenderDrawData(ImGui::GetDrawData(), cmd); }

bool ImGuiLayer::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool ImGuiLayer::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

}  // namespace vkw::window
