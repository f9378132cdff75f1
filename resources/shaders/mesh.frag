#version 330 core
// Smooth shading with a camera-fixed key light (the same light as the software renderer, plus a
// highlight). Inside the rings the ring colour replaces the tissue colour; elsewhere the
// displacement tints it. The wireframe is blended in near the triangle's edges.
in vec3 fPositionView;
in vec3 fNormalView;
in float fPressed;
flat in vec4 fRingColor;
noperspective in vec3 fEdgePx;

uniform vec3 uTissueColor;
uniform vec3 uPressedColor;
uniform vec3 uLightDirView;  // normalised, towards the light
uniform float uAmbient;
uniform float uSpecular;     // the highlight's strength and exponent (SceneStyle.h)
uniform float uShininess;
uniform float uRingAmbient;  // more ambient inside the rings: their colours must read on any face
uniform bool uWireframe;
uniform vec4 uWireColor;     // rgb, and the opacity of a line's centre
uniform vec3 uBackground;    // the see-through view fades the surface towards it
uniform float uOpacity;      // 1, or SceneStyle.h's kSeeThroughOpacity while a lump is shown inside

out vec4 fragColor;

void main() {
    vec3 toEye = normalize(-fPositionView);
    vec3 n = normalize(fNormalView);
    if (dot(n, toEye) < 0.0) n = -n;  // two-sided, whatever the winding: open meshes show their inside
    float diffuse = max(dot(n, uLightDirView), 0.0);
    float specular = uSpecular * pow(max(dot(n, normalize(uLightDirView + toEye)), 0.0), uShininess);
    vec3 base = mix(uTissueColor, uPressedColor, clamp(fPressed, 0.0, 1.0));
    base = mix(base, fRingColor.rgb, fRingColor.a);
    float ambient = mix(uAmbient, uRingAmbient, fRingColor.a);
    vec3 color = base * (ambient + (1.0 - ambient) * diffuse) + vec3(specular);
    if (uWireframe) {
        // A pixel wide (each side of an edge draws its half), fading out over the next half pixel.
        float d = min(fEdgePx.x, min(fEdgePx.y, fEdgePx.z));
        float line = 1.0 - smoothstep(0.5, 1.0, d);
        color = mix(color, uWireColor.rgb, uWireColor.a * line);
    }
    // Mixed with the background rather than blended: the picture stays opaque (it is grabbed) and the
    // software renderer does the same.
    fragColor = vec4(mix(uBackground, color, uOpacity), 1.0);
}
