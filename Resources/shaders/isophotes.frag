// Isophotes: lines of equal light intensity N . L (appearance.txt section 6.3, figure 6),
// drawn as lines of constant width in pixels over diffuse shading. Where two surfaces meet
// with G1 but not G2 continuity the lines keep their position but bend (kink); at a G0
// joint they jump.
#version 120

uniform vec3 lightDirection;  // towards the light
uniform int lockToObject;     // 1: lightDirection is in object coordinates; 0: eye coordinates
uniform float lineCount;      // isophotes over the intensity range [-1, 1]
uniform float lineWidth;      // in pixels
uniform vec3 surfaceColor;
uniform vec3 lineColor;

varying vec3 eyeNormal;
varying vec3 eyePosition;

// Direction from the surface point towards the viewer: constant for an orthographic camera.
vec3 towardsViewer()
{
    return gl_ProjectionMatrix[3][3] == 1.0 ? vec3(0.0, 0.0, 1.0) : normalize(-eyePosition);
}

void main()
{
    vec3 n = normalize(eyeNormal);
    if (dot(n, towardsViewer()) < 0.0) n = -n;  // the back of an open surface
    vec3 light = lockToObject == 1 ? gl_NormalMatrix * lightDirection : lightDirection;
    light = normalize(light);
    float intensity = dot(n, light);

    // distance to the nearest isophote, in pixels, from the screen-space rate of change
    float level = 0.5 * (intensity + 1.0) * lineCount;
    float rate = max(fwidth(level), 1e-6);
    float distancePixels = abs(fract(level + 0.5) - 0.5) / rate;
    float line = 1.0 - smoothstep(0.5 * lineWidth - 0.5, 0.5 * lineWidth + 0.5, distancePixels);

    float diffuse = 0.25 + 0.75 * max(intensity, 0.0);
    gl_FragColor = vec4(mix(surfaceColor * diffuse, lineColor, line), 1.0);
}
