// The Blackboard's sections as types. Each section holds one representation
// type (agent/blackboard/), so a module names what it reads and writes by
// type; SectionOf<T> gives that section's id and the field itself, and
// sectionName(id) its name (the Blackboard's field name). All of it is
// generated from the one list of sections, SIMSWIFT_BLACKBOARD_SECTIONS
// (agent/blackboard/Blackboard.hpp).
#pragma once

#include "agent/blackboard/Blackboard.hpp"

namespace agent::framework {

// One id per Blackboard section, in the list's order.
enum class SectionId : int {
#define SIMSWIFT_SECTION_ID(Type, Id, field) Id,
  SIMSWIFT_BLACKBOARD_SECTIONS(SIMSWIFT_SECTION_ID)
#undef SIMSWIFT_SECTION_ID
  NUM_SECTIONS
};
constexpr int kNumSections = static_cast<int>(SectionId::NUM_SECTIONS);

// The sections' names by id: their Blackboard field names.
inline constexpr const char* kSectionNames[kNumSections] = {
#define SIMSWIFT_SECTION_NAME(Type, Id, field) #field,
    SIMSWIFT_BLACKBOARD_SECTIONS(SIMSWIFT_SECTION_NAME)
#undef SIMSWIFT_SECTION_NAME
};
// "?" for an id outside the list.
constexpr const char* sectionName(SectionId s) {
  const int i = static_cast<int>(s);
  return i >= 0 && i < kNumSections ? kSectionNames[i] : "?";
}

template <class T>
struct SectionOf;  // defined for each representation a Blackboard section holds

#define SIMSWIFT_SECTION_OF(Type, Id, field)                                                                \
  template <>                                                                                               \
  struct SectionOf<blackboard::Type> {                                                                      \
    static constexpr SectionId id = SectionId::Id;                                                          \
    static blackboard::Section<blackboard::Type>& of(blackboard::Blackboard& b) { return b.field; }         \
  };
SIMSWIFT_BLACKBOARD_SECTIONS(SIMSWIFT_SECTION_OF)
#undef SIMSWIFT_SECTION_OF

}  // namespace agent::framework
