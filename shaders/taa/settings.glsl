// The GLSL side of shaders/common/taa_settings.h: named constants for every enum value and
// uniform slot, the TaaSettings struct the includes take, and its defaults.
#ifndef TAA_SETTINGS_GLSL
#define TAA_SETTINGS_GLSL

#define TAA_GLSL_VALUE(cxx, glsl, value, name) const int glsl = value;
TAA_RESOLVE_VALUES(TAA_GLSL_VALUE)
TAA_TONE_WEIGHT_VALUES(TAA_GLSL_VALUE)
TAA_USE_VELOCITY_VALUES(TAA_GLSL_VALUE)
TAA_VELOCITY_SAMPLING_VALUES(TAA_GLSL_VALUE)
TAA_HISTORY_FILTER_VALUES(TAA_GLSL_VALUE)
TAA_RECTIFY_VALUES(TAA_GLSL_VALUE)
TAA_COLOR_SPACE_VALUES(TAA_GLSL_VALUE)
TAA_HISTORY_FORMAT_VALUES(TAA_GLSL_VALUE)
TAA_DEBUG_OUTPUT_VALUES(TAA_GLSL_VALUE)

#define TAA_GLSL_SLOT_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_GLSL_SLOT_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_GLSL_SLOT_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) const int name = slot;
TAA_SETTINGS(TAA_GLSL_SLOT_E, TAA_GLSL_SLOT_B, TAA_GLSL_SLOT_F)

// What the shader includes (shaders/taa/*.glsl) take instead of reading an includer's
// globals: the resolve fills it from its constants and uniforms, TSCMAA from its own.
#define TAA_GLSL_FIELD_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) int key;
#define TAA_GLSL_FIELD_B(key, def, id, name, modes, reads, rule, text, doc, impl) bool key;
#define TAA_GLSL_FIELD_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) float key;
struct TaaSettings {
  TAA_SETTINGS(TAA_GLSL_FIELD_E, TAA_GLSL_FIELD_B, TAA_GLSL_FIELD_F)
};

#define TAA_GLSL_DEFAULT_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl) s.key = def;
#define TAA_GLSL_DEFAULT_B(key, def, id, name, modes, reads, rule, text, doc, impl) s.key = def;
#define TAA_GLSL_DEFAULT_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) s.key = def;
TaaSettings taaDefaultSettings() {
  TaaSettings s;
  TAA_SETTINGS(TAA_GLSL_DEFAULT_E, TAA_GLSL_DEFAULT_B, TAA_GLSL_DEFAULT_F)
  return s;
}

// A selector on an enum says how many values it has branches for: a value added to the
// enum's TAA_<ENUM>_VALUES list then fails to compile at every selector until it has its
// branch (as Granite's #error on an unknown variant), never falling into another's.
#define TAA_GLSL_COUNT_ONE(cxx, glsl, value, name) +1
#define TAA_VALUE_COUNT(values) (0 values(TAA_GLSL_COUNT_ONE))

// A float setting's value in a TaaUniforms block.
#define TAA_SETTING(u, slot) ((u).settings[(slot) / 4][(slot) % 4])
#endif
