// The recording's message schemas (JSON Schema, encoding "jsonschema"): the
// Foxglove schemas' field names and types where one fits (docs.foxglove.dev,
// "Message schemas": FrameTransforms, SceneUpdate, CompressedImage, Log),
// so Foxglove and Lichtblick show them without a plugin; simswift's own
// (simswift.*) where none does. docs/recording.md lists the topics.
#pragma once

#include <string>

namespace simswift::record {

// The JSON Schema text of schema `name` ("foxglove.FrameTransforms", ...);
// throws std::out_of_range for a name not listed here.
const std::string& jsonSchema(const std::string& name);

}  // namespace simswift::record
