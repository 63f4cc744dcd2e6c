#include "snaxels/export/output_file.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cstring>
#include <filesystem>

#include <nlohmann/json.hpp>
#include <zip.h>
#include <zlib.h>

#include "snaxels/error.h"
#include "snaxels/util/atomic_file.h"
#include "snaxels/version.h"

namespace snaxels {

namespace {

struct Extension {
    const char* ext;
    OutputKind kind;
};
constexpr std::array<Extension, 7> kExtensions{{{".svg", OutputKind::Svg},
                                                {".svgz", OutputKind::Svgz},
                                                {".json", OutputKind::Lottie},
                                                {".lottie", OutputKind::DotLottie},
                                                {".mp4", OutputKind::Mp4},
                                                {".webm", OutputKind::Webm},
                                                {".gif", OutputKind::Gif}}};

/// A growing buffer with a position, as minizip's file functions see it:
/// the zip is assembled in memory (it is the compressed document, a
/// fraction of its size) and written to the file at the end.
struct MemoryZip {
    std::string data;
    std::size_t pos = 0;
};

voidpf zip_open(voidpf opaque, const void*, int) { return opaque; }
uLong zip_read(voidpf, voidpf stream, void* buf, uLong size) {
    auto& m = *static_cast<MemoryZip*>(stream);
    const std::size_t n = std::min<std::size_t>(size, m.data.size() - std::min(m.pos, m.data.size()));
    std::memcpy(buf, m.data.data() + m.pos, n);
    m.pos += n;
    return uLong(n);
}
uLong zip_write(voidpf, voidpf stream, const void* buf, uLong size) {
    auto& m = *static_cast<MemoryZip*>(stream);
    if (m.pos + size > m.data.size()) m.data.resize(m.pos + size);
    std::memcpy(m.data.data() + m.pos, buf, size);
    m.pos += size;
    return size;
}
ZPOS64_T zip_tell(voidpf, voidpf stream) { return static_cast<MemoryZip*>(stream)->pos; }
long zip_seek(voidpf, voidpf stream, ZPOS64_T offset, int origin) {
    auto& m = *static_cast<MemoryZip*>(stream);
    std::size_t base = 0;
    if (origin == ZLIB_FILEFUNC_SEEK_CUR) base = m.pos;
    else if (origin == ZLIB_FILEFUNC_SEEK_END) base = m.data.size();
    m.pos = base + offset;
    return 0;
}
int zip_close(voidpf, voidpf) { return 0; }
int zip_error(voidpf, voidpf) { return 0; }

} // namespace

std::optional<OutputKind> output_kind_for(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    for (const Extension& e : kExtensions)
        if (ext == e.ext) return e.kind;
    return std::nullopt;
}

std::string output_extensions() {
    std::string out;
    for (const Extension& e : kExtensions) out += (out.empty() ? "" : ", ") + std::string(e.ext);
    return out;
}

bool is_video(OutputKind kind) { return kind == OutputKind::Mp4 || kind == OutputKind::Webm || kind == OutputKind::Gif; }

AnimationFormat document_format(OutputKind kind) {
    return kind == OutputKind::Lottie || kind == OutputKind::DotLottie ? AnimationFormat::Lottie : AnimationFormat::Svg;
}

DocumentEncoding document_encoding(OutputKind kind) {
    if (kind == OutputKind::Svgz) return DocumentEncoding::Gzip;
    if (kind == OutputKind::DotLottie) return DocumentEncoding::DotLottie;
    return DocumentEncoding::Plain;
}

std::string dotlottie_id_for(const std::string& path) {
    std::string id = std::filesystem::path(path).stem().string();
    for (char& c : id)
        if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '-') c = '_';
    return id.empty() ? "animation" : id;
}

struct DocumentFile::Impl {
    std::string path;
    DocumentEncoding encoding;
    std::string id;
    AtomicFile file;
    z_stream gzip{};
    bool gzip_open = false;
    MemoryZip zip_buffer;
    zipFile zip = nullptr;
    std::string out; ///< encoded bytes waiting for the file

    Impl(const std::string& p, DocumentEncoding e, std::string animation_id)
        : path(p), encoding(e), id(std::move(animation_id)), file(p) {
        if (encoding == DocumentEncoding::Gzip) {
            // Window bits 15 + 16: a gzip header and trailer (time 0: the
            // same document gives the same bytes).
            if (deflateInit2(&gzip, 9, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY) != Z_OK)
                throw Error("cannot write " + path + ": zlib could not start compressing");
            gzip_open = true;
        } else if (encoding == DocumentEncoding::DotLottie) {
            zlib_filefunc64_def io{};
            io.zopen64_file = zip_open;
            io.zread_file = zip_read;
            io.zwrite_file = zip_write;
            io.ztell64_file = zip_tell;
            io.zseek64_file = zip_seek;
            io.zclose_file = zip_close;
            io.zerror_file = zip_error;
            io.opaque = &zip_buffer;
            zip = zipOpen2_64("memory", APPEND_STATUS_CREATE, nullptr, &io);
            if (!zip) throw Error("cannot write " + path + ": the zip could not be started");
            open_entry("animations/" + id + ".json");
        }
    }
    ~Impl() {
        if (gzip_open) deflateEnd(&gzip);
        if (zip) zipClose(zip, nullptr);
    }

    void open_entry(const std::string& name) {
        zip_fileinfo info{};
        info.tmz_date.tm_year = 1980; // a fixed date: the same document gives the same bytes
        info.tmz_date.tm_mday = 1;
        if (zipOpenNewFileInZip64(zip, name.c_str(), &info, nullptr, 0, nullptr, 0, nullptr, Z_DEFLATED, 9, 0) != ZIP_OK)
            throw Error("cannot write " + path + ": the zip entry " + name + " could not be started");
    }
    void zip_write_piece(std::string_view piece) {
        if (zipWriteInFileInZip(zip, piece.data(), unsigned(piece.size())) != ZIP_OK)
            throw Error("cannot write " + path + ": compressing into the zip failed");
    }

    void deflate_piece(std::string_view piece, int flush) {
        gzip.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(piece.data()));
        gzip.avail_in = uInt(piece.size());
        std::array<char, 1 << 16> buffer;
        int rc = Z_OK;
        do {
            gzip.next_out = reinterpret_cast<Bytef*>(buffer.data());
            gzip.avail_out = uInt(buffer.size());
            rc = deflate(&gzip, flush);
            if (rc == Z_STREAM_ERROR) throw Error("cannot write " + path + ": gzip compression failed");
            out.append(buffer.data(), buffer.size() - gzip.avail_out);
        } while (gzip.avail_out == 0 || (flush == Z_FINISH && rc != Z_STREAM_END));
        flush_out(false);
    }
    void flush_out(bool all) {
        if (all || out.size() > (1u << 20)) {
            file.write(out);
            out.clear();
        }
    }
};

DocumentFile::DocumentFile(const std::string& path, DocumentEncoding encoding, const std::string& animation_id)
    : impl_(std::make_unique<Impl>(path, encoding, animation_id)) {}

DocumentFile::~DocumentFile() = default;

void DocumentFile::write(std::string_view piece) {
    document_bytes_ += piece.size();
    // Large pieces go in slices the 32-bit sizes of zlib and minizip hold.
    while (!piece.empty()) {
        const std::string_view slice = piece.substr(0, std::size_t{1} << 30);
        piece.remove_prefix(slice.size());
        switch (impl_->encoding) {
        case DocumentEncoding::Plain:
            impl_->out.append(slice);
            impl_->flush_out(false);
            break;
        case DocumentEncoding::Gzip: impl_->deflate_piece(slice, Z_NO_FLUSH); break;
        case DocumentEncoding::DotLottie: impl_->zip_write_piece(slice); break;
        }
    }
}

void DocumentFile::finish() {
    Impl& m = *impl_;
    if (m.encoding == DocumentEncoding::Gzip) {
        m.deflate_piece({}, Z_FINISH);
    } else if (m.encoding == DocumentEncoding::DotLottie) {
        if (zipCloseFileInZip(m.zip) != ZIP_OK) throw Error("cannot write " + m.path + ": closing the zip entry failed");
        // The manifest (dotLottie 1.0): the one animation, playing in a loop.
        const nlohmann::json manifest = {
            {"version", "1"},
            {"generator", std::string("snaxels ") + version},
            {"author", ""},
            {"activeAnimationId", m.id},
            {"animations",
             {{{"id", m.id}, {"speed", 1}, {"loop", true}, {"autoplay", true}, {"direction", 1}, {"playMode", "normal"}}}}};
        m.open_entry("manifest.json");
        m.zip_write_piece(manifest.dump(1) + "\n");
        if (zipCloseFileInZip(m.zip) != ZIP_OK) throw Error("cannot write " + m.path + ": closing the zip entry failed");
        const int rc = zipClose(m.zip, nullptr);
        m.zip = nullptr;
        if (rc != ZIP_OK) throw Error("cannot write " + m.path + ": finishing the zip failed");
        m.out += m.zip_buffer.data;
        m.zip_buffer = {};
    }
    m.flush_out(true);
    m.file.commit();
}

} // namespace snaxels
