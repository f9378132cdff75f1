#version 330 core
// One colour, usually translucent (blended): wire edges, the ghost's surface and edges.
in float vMoved;  // > 0 inside a triangle with a moved corner

uniform vec4 uColor;
uniform bool uOnlyMoved;  // the ghost: nothing where the tissue is at rest

out vec4 fragColor;

void main() {
    if (uOnlyMoved && vMoved <= 0.0) discard;
    fragColor = uColor;
}
