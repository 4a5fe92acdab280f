#version 330 core
in vec4 vColor;
uniform bool roundPoints;
uniform vec4 tint;
out vec4 fragColor;
void main() {
  if (roundPoints && length(gl_PointCoord - vec2(0.5)) > 0.5) discard;
  fragColor = vColor * tint;
}
