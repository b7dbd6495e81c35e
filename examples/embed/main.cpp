// tessera-embed: a minimal game on Tessera's runtime, built against the
// installed package alone. It picks a backend by name, draws the terrain
// with a crowd of tessellated creatures from a camera it places itself, and
// asks the same terrain the GPU draws gameplay questions: the ground height
// under a point, and what a crater does to it. It takes its options with
// the package's command-line library (Tessera::cli, the parser of every
// Tessera program) and names the runtime's settings by its own flags in the
// runtime's messages (runtime::Reporter).
//
//   tessera-embed [--backend NAME] [--window] [--validation] [--frames N]
//                 [--agents N] [--screenshot FILE]

#include "tessera/cli/CommandLine.h"
#include "tessera/cli/Validators.h"
#include "tessera/core/ImageFile.h"
#include "tessera/crowd/Crowd.h"
#include "tessera/runtime/BackendSelection.h"
#include "tessera/runtime/Options.h"
#include "tessera/runtime/Reporter.h"
#include "tessera/runtime/SceneRun.h"
#include "tessera/runtime/Settings.h"
#include "tessera/runtime/SimulatedCrowd.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace {

struct GameFlags {
    std::string backend; // empty: the best the device runs
    bool window = false;
    bool validation = false;
    uint32_t frames = 30;
    uint32_t agents = 300;
    std::string screenshot;
};

/// The game's own command line; false after printing what is wrong (or the
/// help), with the exit code in `code`.
bool parseFlags(int argc, char** argv, GameFlags& flags, int& code) {
    tessera::cli::CommandLine line("tessera-embed", "A minimal game on Tessera's runtime: a crowd on the terrain, "
                                                    "a crater halfway through, headless unless --window.");
    CLI::App& app = line.app();
    app.add_option("--backend", flags.backend, "the backend (default: the best the device runs)")->type_name("NAME");
    app.add_flag("--window", flags.window, "open a window instead of rendering headless");
    app.add_flag("--validation", flags.validation, "enable the Khronos validation layer; fail on any message");
    app.add_option("--frames", flags.frames, "frames to draw (default 30)")
        ->type_name("N")
        ->check(tessera::cli::count(1, 100000));
    app.add_option("--agents", flags.agents, "agents in the crowd (default 300)")
        ->type_name("N")
        ->check(tessera::cli::count(1, tessera::crowd::Crowd::kMaxAgents));
    app.add_option("--screenshot", flags.screenshot, "write the last frame as PNG")->type_name("FILE");
    auto parsed = line.parse(argc, argv);
    if (!parsed) {
        std::fprintf(stderr, "tessera-embed: %s\n", parsed.error().message.c_str());
        code = 2;
        return false;
    }
    if (!parsed.value()) {
        std::fputs(line.help().c_str(), stdout);
        code = 0;
        return false;
    }
    return true;
}

/// The runtime words its messages itself; the game puts its own flags in
/// place of the settings it takes (the runtime's words for the rest).
class GameNames final : public tessera::runtime::Reporter {
public:
    std::string name(std::string_view words) const override {
        namespace setting = tessera::runtime::setting;
        if (words == setting::kBackend) return "--backend";
        if (words == setting::kAgents) return "--agents";
        if (words == setting::kScreenshot) return "--screenshot";
        return std::string(words);
    }
};

/// A camera at `eye` looking at `target`, in Tessera's conventions (yaw 0
/// looks toward -Z and turns toward -X; pitch up is positive).
tessera::scene::CameraPose lookAt(const glm::vec3& eye, const glm::vec3& target) {
    const glm::vec3 d = target - eye;
    return {eye, std::atan2(-d.x, -d.z), std::atan2(d.y, std::sqrt(d.x * d.x + d.z * d.z))};
}

} // namespace

int main(int argc, char** argv) {
    using namespace tessera;
    GameFlags flags;
    if (int code = 0; !parseFlags(argc, argv, flags, code)) return code;

    const GameNames names;
    runtime::Options options; // every field has a working default
    options.reporter = &names;
    options.backend = flags.backend;
    options.window = flags.window;
    options.validation = flags.validation;
    options.width = 960;
    options.height = 540;
    options.scene = "crowd";
    options.agents = {flags.agents};
    auto created = runtime::SceneRun::create(options, flags.frames);
    if (!created) {
        std::fprintf(stderr, "tessera-embed: %s\n", names.wording(created.error()).c_str());
        return 1;
    }
    runtime::SceneRun& run = *created.value();
    runtime::World& world = run.world();
    terrain::Terrain& ground = world.terrain();

    // The game's camera: 25 m from the crowd's centre, 8 m above the ground.
    const glm::vec2 centre = world.simulatedCrowd()->layout().spawn.center;
    const glm::vec3 target(centre.x, ground.heightAt(centre.x, centre.y), centre.y);
    const glm::vec3 eye(centre.x + 25.0f, ground.heightAt(centre.x + 25.0f, centre.y) + 8.0f, centre.y);
    world.fixCamera(lookAt(eye, target));

    // Gameplay: a crater 10 m from the centre, halfway through; the ground
    // the creatures walk on and the GPU's height map change together.
    const glm::vec2 impact = centre + glm::vec2(0.0f, 10.0f);
    const float before = ground.heightAt(impact.x, impact.y);
    float after = before;
    uint32_t frame = 0;
    for (; frame < flags.frames; ++frame) {
        if (frame == flags.frames / 2) {
            ground.splat(impact, 6.0f);
            after = ground.heightAt(impact.x, impact.y);
        }
        const bool last = frame + 1 == flags.frames;
        if (!run.step(frame, last && !flags.screenshot.empty())) break;
    }
    const std::vector<uint8_t> pixels = run.session().finish();
    if (!flags.screenshot.empty()) {
        if (Status ok = writePng(flags.screenshot, {run.session().width(), run.session().height(), pixels}); !ok) {
            std::fprintf(stderr, "tessera-embed: %s\n", names.wording(ok.error()).c_str());
            return 1;
        }
    }
    std::printf("backend %s on %s: %u frames, %u agents\n", run.session().capabilities().name.c_str(),
                run.session().deviceName().c_str(), frame, flags.agents);
    std::printf("ground at the crater: %.2f m before, %.2f m after (%.2f m deep)\n", before, after, before - after);
    std::printf("%s\n", world.simulatedCrowd()->summary().c_str());
    created.value().reset(); // every Vulkan object gone before counting messages
    if (flags.validation) {
        const uint64_t messages = runtime::validationMessages();
        std::printf("validation messages: %llu\n", static_cast<unsigned long long>(messages));
        if (messages > 0) return 1;
    }
    return before - after > 0.0f ? 0 : 1;
}
