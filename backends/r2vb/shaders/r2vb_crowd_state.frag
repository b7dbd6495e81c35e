#version 450
// Pass crowd.state (r2vb): writes the state word the point carries.
layout(location = 0) flat in uint inState;
layout(location = 0) out uint outState;

void main() {
    outState = inState;
}
