#version 330 core
// Tissue surface: positions in mm, per-vertex normals recomputed from the deformed shape (only
// around the vertices that moved), how pressed each vertex looks (0..1, from its displacement), and
// its ring of the touched vertex (0 = touched, 255 = none), passed on to the geometry shader.
layout(location = 0) in vec3 aPositionMm;
layout(location = 1) in vec3 aNormal;
layout(location = 2) in float aPressed;
layout(location = 3) in uint aRing;

uniform mat4 uView;        // rigid: its upper 3x3 maps normals too
uniform mat4 uProjection;

out VertexData {
    vec3 positionView;
    vec3 normalView;
    float pressed;
    flat uint ring;
} vOut;

// The same depth as flat.vert's for the same position: the ghost's depth offsets rely on it.
invariant gl_Position;

void main() {
    vec4 positionView = uView * vec4(aPositionMm, 1.0);
    vOut.positionView = positionView.xyz;
    vOut.normalView = mat3(uView) * aNormal;
    vOut.pressed = aPressed;
    vOut.ring = aRing;
    gl_Position = uProjection * positionView;
}
