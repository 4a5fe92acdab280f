#version 330 core
// A raster drawn as a textured quad on the map plane.
layout(location = 0) in vec3 position;
layout(location = 1) in vec2 uv;
uniform mat4 viewProjection;
out vec2 vUv;
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  vUv = uv;
}
