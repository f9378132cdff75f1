#version 330 core
// Smooth shading with a camera-fixed key light (the same light as the software renderer, plus a
// highlight), or a flat colour for the wireframe pass.
in vec3 vPositionView;
in vec3 vNormalView;
in float vPressed;

uniform bool uWirePass;
uniform vec4 uWireColor;
uniform vec3 uTissueColor;
uniform vec3 uPressedColor;
uniform vec3 uLightDirView;  // normalised, towards the light
uniform float uAmbient;

out vec4 fragColor;

void main() {
    if (uWirePass) {
        fragColor = uWireColor;
        return;
    }
    vec3 toEye = normalize(-vPositionView);
    vec3 n = normalize(vNormalView);
    if (dot(n, toEye) < 0.0) n = -n;  // two-sided, whatever the winding: open meshes show their inside
    float diffuse = max(dot(n, uLightDirView), 0.0);
    float specular = 0.18 * pow(max(dot(n, normalize(uLightDirView + toEye)), 0.0), 40.0);
    vec3 base = mix(uTissueColor, uPressedColor, clamp(vPressed, 0.0, 1.0));
    fragColor = vec4(base * (uAmbient + (1.0 - uAmbient) * diffuse) + vec3(specular), 1.0);
}
