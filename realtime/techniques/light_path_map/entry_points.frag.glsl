// The entry points' colour in the entry-point figure.
layout(location = 0) out vec4 o_radiance;

void main() { o_radiance = vec4(1.0, 0.8, 0.1, 1.0); }
