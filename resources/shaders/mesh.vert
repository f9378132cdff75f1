#version 330 core
// Tissue surface: positions in mm, per-vertex normals recomputed each frame from the deformed shape,
// and how pressed each vertex looks (0..1, from its displacement).
layout(location = 0) in vec3 aPositionMm;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aPressed;

uniform mat4 uView;        // rigid: its upper 3x3 maps normals too
uniform mat4 uProjection;

out vec3 vPositionView;
out vec3 vNormalView;
out float vPressed;

void main() {
    vec4 positionView = uView * vec4(aPositionMm, 1.0);
    vPositionView = positionView.xyz;
    vNormalView = mat3(uView) * aNormal;
    vPressed = aPressed;
    gl_Position = uProjection * positionView;
}
