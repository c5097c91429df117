#include "tools/vkwater/commands.hpp"

namespace vkw::cli {

void add_device_options(CLI::App& command, DeviceOptions& options) {
    command.add_option("--device", options.device,
                       "Use the Vulkan device whose name contains this text (default: a discrete, then an "
                       "integrated GPU, then the CPU device lavapipe)");
    command.add_flag("--validation", options.validation,
                     "Run with VK_LAYER_KHRONOS_validation and synchronization validation; any error or "
                     "warning fails the run (exit 2)");
}

}  // namespace vkw::cli
