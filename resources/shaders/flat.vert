#version 330 core
// Positions only, for the passes drawn in one colour: the wireframe and the rest-shape ghost. For
// the ghost, aPressed is the deformed vertex's pressed weight: only triangles with a moved corner
// are drawn (flat.frag), as in the software renderer.
layout(location = 0) in vec3 aPositionMm;
layout(location = 2) in float aPressed;

uniform mat4 uView;
uniform mat4 uProjection;

out float vMoved;

// The same depth as mesh.vert's for the same position: the ghost's depth offsets rely on it.
invariant gl_Position;

void main() {
    vMoved = aPressed > 0.0 ? 1.0 : 0.0;
    gl_Position = uProjection * (uView * vec4(aPositionMm, 1.0));
}
