// A bundle ray's sample and one count, added into its patch's texel (additive blending).
in vec3 v_sample;
layout(location = 0) out vec4 o_sum;

void main() { o_sum = vec4(v_sample, 1.0); }
