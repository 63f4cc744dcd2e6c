#pragma once
/// The files an animation can be written as, chosen by the output's
/// extension, and the compressed containers of its documents: gzip for
/// `.svgz` and the dotLottie zip for `.lottie`.

#include <memory>
#include <optional>
#include <string>
#include <string_view>

#include "snaxels/export/animation_writer.h"

namespace snaxels {

/// What an animation's output file holds.
enum class OutputKind {
    Svg,       ///< .svg: animated SVG
    Svgz,      ///< .svgz: animated SVG, gzip-compressed (browsers and Inkscape read it)
    Lottie,    ///< .json: Lottie
    DotLottie, ///< .lottie: the dotLottie container (a zip of a manifest and the Lottie)
    Mp4,       ///< .mp4: H.264 video (core/export/video.h)
    Webm,      ///< .webm: VP9 video
    Gif,       ///< .gif: animated GIF
};

/// The kind @p path's extension (any case) asks for, or none for an
/// extension no output has.
std::optional<OutputKind> output_kind_for(const std::string& path);

/// The extensions output_kind_for knows, for messages: ".svg, .svgz, ...".
std::string output_extensions();

/// Whether the kind is a video (the frames rendered and encoded) rather
/// than a document of moving paths.
bool is_video(OutputKind kind);

/// The document a non-video kind holds (SVG or Lottie).
AnimationFormat document_format(OutputKind kind);

/// How a document's bytes are stored in its file.
enum class DocumentEncoding {
    Plain,     ///< as they are
    Gzip,      ///< one gzip member (.svgz)
    DotLottie, ///< a zip: manifest.json and animations/ANIMATION.json (.lottie)
};

DocumentEncoding document_encoding(OutputKind kind);

/// Writes a document to @p path as it comes, in pieces, encoded as asked,
/// atomically: the file appears, whole, at finish(); destroyed before
/// that (an error, a cancel), it leaves the path as it was. Errors throw
/// snaxels::Error naming the path.
class DocumentFile {
  public:
    /// @p animation_id names the animation inside a dotLottie (its file
    /// name and manifest id); ignored by the other encodings.
    DocumentFile(const std::string& path, DocumentEncoding encoding, const std::string& animation_id = "animation");
    ~DocumentFile();
    DocumentFile(const DocumentFile&) = delete;
    DocumentFile& operator=(const DocumentFile&) = delete;

    void write(std::string_view piece);
    /// Closes the encoding and puts the file in place.
    void finish();
    /// The document's bytes so far, before encoding.
    std::size_t document_bytes() const { return document_bytes_; }

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
    std::size_t document_bytes_ = 0;
};

/// The name of a dotLottie's animation made from @p path: its file name
/// without the extension, in the characters the format's ids allow
/// (letters, digits, '_' and '-'; others become '_').
std::string dotlottie_id_for(const std::string& path);

} // namespace snaxels
