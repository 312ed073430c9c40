// The Vulkan validation layers (VK_LAYER_KHRONOS_validation, Debian vulkan-validationlayers,
// installed by scripts/install-deps) watch every registered technique and its tested variants
// render the test scene (a grass field for the grass family): not one warning or error, from instance creation to destruction. The
// layer is required: without it these tests fail and say what to install.
#include "gpu/context.hpp"
#include "support/technique_variants.hpp"
#include "support/test_gpu.hpp"
#include "support/tiny_scene.hpp"

#include <doctest/doctest.h>

#include <memory>
#include <string>

using namespace canopy;

namespace {

constexpr int kWidth = 64, kHeight = 48;

std::string joined(const std::vector<std::string>& messages) {
    std::string out;
    for (const std::string& message : messages) out += "\n  " + message;
    return out;
}

}  // namespace

TEST_CASE("every technique renders without a single validation warning or error") {
    std::shared_ptr<const ValidationLog> log;
    size_t rendered = 0;
    {
        GpuContext context(test::device_selector(), GpuContext::Validation::on);
        log = context.validation_log();
        REQUIRE(log != nullptr);
        const Scene shadow_scene = test::tiny_scene_under_rect_light(0.3f, glm::vec3(0.3f, 4.0f, 0.2f));
        const Scene grass_scene = test::tiny_grass_scene();
        for (const test::TechniqueVariant& variant : test::technique_variants()) {
            const std::string name = test::describe(variant);
            CAPTURE(name);
            const size_t before = log->count();
            const Scene& scene = test::family_of(variant.technique) == "grass" ? grass_scene : shadow_scene;
            test::render_technique(context, scene, variant.technique, variant.params, kWidth, kHeight);
            const std::vector<std::string> messages = log->messages();
            CHECK_MESSAGE(messages.size() == before,
                          "validation messages:" << joined({messages.begin() + long(before), messages.end()}));
            ++rendered;
        }
    }
    CHECK(rendered >= test::technique_variants().size());
    // Objects left alive are reported as the device and the instance are destroyed.
    CHECK_MESSAGE(log->count() == 0, "validation messages:" << joined(log->messages()));
}

TEST_CASE("the validation log hears a misuse, including one reported at destruction") {
    // Can the test above fail? A semaphore never destroyed is an error the layer reports when
    // the device is destroyed, after every render is over.
    std::shared_ptr<const ValidationLog> log;
    {
        GpuContext context(test::device_selector(), GpuContext::Validation::on);
        log = context.validation_log();
        VkSemaphoreCreateInfo info{VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
        VkSemaphore leaked = VK_NULL_HANDLE;
        REQUIRE(vkCreateSemaphore(context.device(), &info, nullptr, &leaked) == VK_SUCCESS);
        CHECK(log->count() == 0);
    }
    REQUIRE(log->count() > 0);
    CHECK(log->messages().front().find("VkSemaphore") != std::string::npos);
}

TEST_CASE("without the validation layer, asking for it fails and names the package to install") {
    // The loader looks for explicit layers in VK_LAYER_PATH alone when it is set.
    const char* previous = std::getenv("VK_LAYER_PATH");
    const std::string saved = previous ? previous : "";
    setenv("VK_LAYER_PATH", "/nonexistent-canopy-test", 1);
    std::string error;
    try {
        GpuContext context(test::device_selector(), GpuContext::Validation::on);
    } catch (const GpuError& e) {
        error = e.what();
    }
    previous ? setenv("VK_LAYER_PATH", saved.c_str(), 1) : unsetenv("VK_LAYER_PATH");
    INFO(error);
    CHECK(error.find("VK_LAYER_KHRONOS_validation") != std::string::npos);
    CHECK(error.find("vulkan-validationlayers") != std::string::npos);
}
