#version 450
// One control point per patch; the control stage ignores its data.
void main() {
}
