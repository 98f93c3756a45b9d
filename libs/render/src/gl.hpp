// SPDX-License-Identifier: MIT
#pragma once

// GLEW must come before any other OpenGL header (GLFW's included).
#include <GL/glew.h>
