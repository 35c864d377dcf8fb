// Constants shared by every stage; pulled in with #include "common.glsl".
const float PI = 3.14159265358979;
const int MAX_LIGHTS = 8;
const int LIGHT_DIRECTIONAL = 0;
const int LIGHT_POINT = 1;
const int LIGHT_SPOT = 2;
const int LIGHT_AREA = 3;
