// Shared vertex stage of the surface-analysis overlays (isophotes, zebra, curvature map).
//
// The normal is the exact surface normal at the vertex (NurbsLOD.analysis_mesh), not the
// facet's: interpolated across the triangle it gives the Phong-style per-pixel normal that
// appearance.txt section 5 assumes, so stripes follow the surface rather than the mesh.
// GLSL 1.20 (compatibility profile): Coin feeds the fixed-function attributes.
#version 120

varying vec3 eyeNormal;    // normal in eye coordinates, not normalised (interpolated)
varying vec3 eyePosition;  // position in eye coordinates
varying float property;    // the scalar the curvature map shows (texture coordinate s)

void main()
{
    eyeNormal = gl_NormalMatrix * gl_Normal;
    vec4 position = gl_ModelViewMatrix * gl_Vertex;
    eyePosition = position.xyz / position.w;
    property = gl_MultiTexCoord0.s;
    gl_Position = ftransform();
}
