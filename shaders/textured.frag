#version 330 core
in vec2 vUv;
uniform sampler2D image;
uniform vec4 tint;
out vec4 fragColor;
void main() {
  fragColor = texture(image, vUv) * tint;
}
