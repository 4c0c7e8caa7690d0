// `vkmc info SCENE`: what the scene needs and what vkmc will run for it.
#pragma once
#include <string>

#include "app/render_job.h"

namespace vkmc {
int runInfo(const RenderOptions& options);
}
