#version 330 core
// Points and lines with a colour per vertex, positions in the city frame relative to the
// scene origin (floats keep centimetres only near it).
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 color;
uniform mat4 viewProjection;
uniform float pointSize;
out vec4 vColor;
void main() {
  gl_Position = viewProjection * vec4(position, 1.0);
  gl_PointSize = pointSize;
  vColor = color;
}
