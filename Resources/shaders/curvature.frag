// Curvature map: the scalar per vertex (Gaussian, mean, minimum or maximum curvature of the
// exact surface, NurbsLOD.analysis_mesh) interpolated across the triangle (appearance.txt
// section 5: additional attributes are interpolated linearly) and looked up in a colour ramp.
#version 120

uniform float rangeMinimum;  // the value shown at the blue end of the ramp
uniform float rangeMaximum;  // the value shown at the red end
uniform float levelCount;    // contour lines between them; 0 for none
uniform sampler2D ramp;      // the colour ramp, left (minimum) to right (maximum)

varying vec3 eyeNormal;
varying vec3 eyePosition;
varying float property;

vec3 towardsViewer()
{
    return gl_ProjectionMatrix[3][3] == 1.0 ? vec3(0.0, 0.0, 1.0) : normalize(-eyePosition);
}

void main()
{
    float span = rangeMaximum - rangeMinimum;
    float t = span > 0.0 ? clamp((property - rangeMinimum) / span, 0.0, 1.0) : 0.5;
    vec3 color = texture2D(ramp, vec2(t, 0.5)).rgb;
    if (levelCount > 0.0 && t > 0.0 && t < 1.0) {  // none where the range clamps
        float level = t * levelCount;
        float distancePixels = abs(fract(level + 0.5) - 0.5) / max(fwidth(level), 1e-6);
        color *= mix(0.6, 1.0, smoothstep(0.5, 1.5, distancePixels));
    }
    // a headlight keeps the shape readable under the colours
    vec3 n = normalize(eyeNormal);
    float light = 0.45 + 0.55 * abs(dot(n, towardsViewer()));
    gl_FragColor = vec4(color * light, 1.0);
}
