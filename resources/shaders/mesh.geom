#version 330 core
// Per triangle: (1) one colour for the rings, the lowest ring among its corners (the software
// renderer uses the same rule), so each ring shows as a band rather than a blend of its neighbours'
// colours; (2) each corner's distance in pixels to the opposite edge, so that the fragment shader
// draws the wireframe in the same pass (a separate line pass costs more than the fill on a software
// rasteriser such as llvmpipe).
layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in VertexData {
    vec3 positionView;
    vec3 normalView;
    float pressed;
    flat uint ring;
} gIn[];

uniform vec3 uRingColors[9];  // touched vertex, rings 1..8
uniform vec2 uViewportPx;     // framebuffer size in pixels

out vec3 fPositionView;
out vec3 fNormalView;
out float fPressed;
flat out vec4 fRingColor;     // rgb, and a = 1 inside a ring, 0 outside
noperspective out vec3 fEdgePx;  // distance to each edge in pixels (min: to the nearest edge)

void main() {
    uint ring = min(min(gIn[0].ring, gIn[1].ring), gIn[2].ring);
    vec4 ringColor = ring < 9u ? vec4(uRingColors[ring], 1.0) : vec4(0.0);

    vec3 heights = vec3(1e6);  // no wire for a triangle reaching behind the eye
    if (gl_in[0].gl_Position.w > 0.0 && gl_in[1].gl_Position.w > 0.0 && gl_in[2].gl_Position.w > 0.0) {
        vec2 p0 = 0.5 * uViewportPx * gl_in[0].gl_Position.xy / gl_in[0].gl_Position.w;
        vec2 p1 = 0.5 * uViewportPx * gl_in[1].gl_Position.xy / gl_in[1].gl_Position.w;
        vec2 p2 = 0.5 * uViewportPx * gl_in[2].gl_Position.xy / gl_in[2].gl_Position.w;
        vec2 e0 = p2 - p1, e1 = p0 - p2, e2 = p1 - p0;
        float area2 = abs(e2.x * -e1.y - e2.y * -e1.x);  // twice the area, in pixels
        heights = area2 / max(vec3(length(e0), length(e1), length(e2)), vec3(1e-6));
    }
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        fPositionView = gIn[i].positionView;
        fNormalView = gIn[i].normalView;
        fPressed = gIn[i].pressed;
        fRingColor = ringColor;
        fEdgePx = vec3(i == 0 ? heights.x : 0.0, i == 1 ? heights.y : 0.0, i == 2 ? heights.z : 0.0);
        EmitVertex();
    }
    EndPrimitive();
}
