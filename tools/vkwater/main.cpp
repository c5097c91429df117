// vkwater: the command-line entry point. Subcommands live in one file each.
#include "engine/core/errors.hpp"
#include "tools/vkwater/commands.hpp"
#include "tools/vkwater/console.hpp"

#include <cstdio>
#include <map>
#include <string>

int main(int argc, char** argv) {
    CLI::App app{"vkwater: a Vulkan renderer for water with compute-shader caustics"};
    app.set_version_flag("--version", "vkwater " VKWATER_VERSION);
    app.require_subcommand(1);
    // Accepted before or after the command (fallthrough): vkwater -q render ..., vkwater render ... -q.
    bool quiet = false, verbose = false;
    app.add_flag("-q,--quiet", quiet, "Print errors only");
    app.add_flag("-v,--verbose", verbose,
                 "Print more: render gives each effect's decision and its reason before the pass times");
    app.fallthrough();
    std::map<CLI::App*, vkw::cli::Run> commands;
    auto add = [&](vkw::cli::Run (*register_command)(CLI::App&)) {
        const size_t before = app.get_subcommands({}).size();
        vkw::cli::Run run = register_command(app);
        commands[app.get_subcommands({})[before]] = std::move(run);
    };
#ifndef VKWATER_LOADERS_ONLY
    add(vkw::cli::add_render_command);
    add(vkw::cli::add_passes_command);
    add(vkw::cli::add_reference_command);
    add(vkw::cli::add_bench_command);
    add(vkw::cli::add_povray_command);
    add(vkw::cli::add_view_command);
#endif
    // The sanitizer build (VKWATER_LOADERS_ONLY) has these two alone: they read files, need no device.
    add(vkw::cli::add_compare_command);
    add(vkw::cli::add_check_command);
    // vkwater help [COMMAND]: the same text as --help, for the habit of git and cargo.
    std::string help_topic;
    CLI::App* help = app.add_subcommand("help", "Print this help, or a command's: vkwater help COMMAND");
    help->add_option("command", help_topic, "A command's name");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help and --version print and exit 0; every other parse error is the user's (exit 1), on
        // one line like every other error (CLI11's own form adds a second line).
        if (error.get_exit_code() == 0) return app.exit(error);
        std::fprintf(stderr, "vkwater: %s (vkwater help [COMMAND] lists the options)\n", error.what());
        return vkw::kExitUserError;
    }
    if (quiet && verbose) {
        std::fprintf(stderr, "vkwater: --quiet and --verbose: choose one\n");
        return vkw::kExitUserError;
    }
    vkw::cli::set_verbosity(quiet     ? vkw::cli::Verbosity::Quiet
                            : verbose ? vkw::cli::Verbosity::Verbose
                                      : vkw::cli::Verbosity::Normal);
    if (help->parsed()) {
        if (help_topic.empty()) {
            // app.help() would print the parsed subcommand's (help's own): format the app itself.
            std::printf("%s", app.get_formatter()->make_help(&app, argv[0], CLI::AppFormatMode::Normal).c_str());
            return vkw::kExitOk;
        }
        for (CLI::App* command : app.get_subcommands({})) {
            if (command->get_name() == help_topic && command != help) {
                std::printf("%s", command->help().c_str());
                return vkw::kExitOk;
            }
        }
        std::fprintf(stderr,
                     "vkwater: help: no command '%s' (accepted: render, passes, reference, compare, bench, "
                     "povray, view, check)\n",
                     help_topic.c_str());
        return vkw::kExitUserError;
    }
    try {
        for (auto& [command, run] : commands) {
            if (command->parsed()) return run();
        }
        return vkw::kExitUserError;
    } catch (const vkw::UserError& error) {
        std::fprintf(stderr, "vkwater: %s\n", error.what());
        return vkw::kExitUserError;
    } catch (const vkw::InternalError& error) {
        std::fprintf(stderr, "vkwater: %s\n", error.what());
        return vkw::kExitInternalError;
    } catch (const std::exception& error) {
        std::fprintf(stderr, "vkwater: internal error: %s\n", error.what());
        return vkw::kExitInternalError;
    }
}
