#version 450
// Pass crowd.nearSlots (r2vb): writes a slot's record and its skin draw.
layout(location = 0) flat in uvec4 inRecord;
layout(location = 1) flat in uvec4 inSkin;
layout(location = 0) out uvec4 outRecord;
layout(location = 1) out uvec4 outSkin;

void main() {
    outRecord = inRecord;
    outSkin = inSkin;
}
