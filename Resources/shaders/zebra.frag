// Reflection lines (zebra stripes): the view ray reflected at the surface hits an
// environment of parallel light tubes (appearance.txt section 6.3, figure 8). The stripe is a
// function of the reflected direction, i.e. of the normal: across a G1 joint the stripes
// stay connected but kink, across a G2 joint they run on smoothly, across G0 they break.
#version 120

uniform vec3 tubeDirection;  // the axis the light tubes run along
uniform int lockToObject;    // 1: tubeDirection in object coordinates; 0: eye coordinates
uniform float stripeCount;   // black stripes around a full turn of the reflected direction
uniform float widthRatio;    // fraction of each period that is black, in (0, 1)
uniform vec3 lightColor;
uniform vec3 darkColor;

varying vec3 eyeNormal;
varying vec3 eyePosition;

const float PI = 3.14159265358979;

vec3 towardsViewer()
{
    return gl_ProjectionMatrix[3][3] == 1.0 ? vec3(0.0, 0.0, 1.0) : normalize(-eyePosition);
}

// 1 inside a black stripe, 0 outside, anti-aliased over one pixel. phase counts periods;
// the black part of each period is [0, widthRatio); rate is the phase change per pixel.
float stripe(float phase, float rate)
{
    float f = fract(phase);
    float h = 0.5 * rate;
    float inside = smoothstep(-h, h, f) * (1.0 - smoothstep(widthRatio - h, widthRatio + h, f));
    float nextStart = smoothstep(1.0 - h, 1.0 + h, f);  // the next period's stripe, near f = 1
    return clamp(inside + nextStart, 0.0, 1.0);
}

void main()
{
    vec3 view = towardsViewer();
    vec3 n = normalize(eyeNormal);
    if (dot(n, view) < 0.0) n = -n;
    vec3 reflected = reflect(-view, n);

    vec3 axis = lockToObject == 1 ? gl_NormalMatrix * tubeDirection : tubeDirection;
    axis = normalize(axis);
    // two directions across the tubes; the helper is any vector not along the axis
    vec3 helper = abs(axis.z) < 0.9 ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 across = normalize(cross(axis, helper));
    vec3 across2 = cross(axis, across);

    float angle = atan(dot(reflected, across2), dot(reflected, across));  // (-pi, pi]
    float phase = (angle / (2.0 * PI) + 0.5) * stripeCount;
    // the same phase with its wrap-around half a turn away: its rate is right where the
    // first one jumps from stripeCount back to 0
    float shifted = fract(angle / (2.0 * PI) + 1.0) * stripeCount;
    float rate = min(fwidth(phase), fwidth(shifted));

    float black = stripe(phase, rate);
    float shade = 0.55 + 0.45 * abs(dot(n, view));
    gl_FragColor = vec4(mix(lightColor * shade, darkColor, black), 1.0);
}
