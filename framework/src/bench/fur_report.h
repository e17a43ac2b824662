#pragma once
// The report of `raylab bench --track fur`: the source thesis's evaluation
// criteria measured here - frame time against triangle count for shells and
// fins (several shell counts) and the fur shader, memory, and quality (each
// shell count against a rendering with many shells) - as fur.csv, fur.md and
// fur.png. Text output is deterministic: the same rows give the same files.
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace raylab {

struct FurRow {
    std::string technique;  // "shells_and_fins" or "fur_shader"
    std::string mesh;       // "sphere"
    long triangles = 0;
    int shells = 0;  // draw calls of the shell program (the skin's included); 1 for the fur shader
    bool fins = false;
    double frameMs = 0;
    std::size_t bufferBytes = 0;  // GPU buffers and textures this technique reads
    std::size_t rssBytes = 0;     // the process's resident memory after the row's frames
    double rmse = 0;              // 0..1 against the quality reference; NaN: not comparable
    double badPxShare = 0;        // 0..1 pixels off by more than the graders' tolerance; NaN: idem
};

// A row's series in the plot and tables: "shells+fins 16", "fur shader".
std::string furSeriesName(const FurRow& row);

// technique,mesh,triangles,shells,fins,frame_ms,buffer_bytes,rss_bytes,rmse,bad_px_share
// (RFC 4180, CRLF; NaN as an empty field).
std::string furCsv(const std::vector<FurRow>& rows);

// "# TITLE", the command, NOTES (Markdown: the reference, the GPU limits),
// then frame time by triangle count (one column per series), the fur shader
// against shells and fins as ratios, quality per shell count, and memory.
std::string furMarkdown(const std::vector<FurRow>& rows, const std::string& title,
                        const std::string& commandLine, const std::string& notes,
                        const std::string& plotFile = "");

// fur.png: frame time (ms, log) against triangles (log), one line per
// series. Throws Error like writeBenchPlot (gnuplot missing or failing).
void writeFurPlot(const std::vector<FurRow>& rows, const std::filesystem::path& pngPath,
                  const std::string& title, const std::string& gnuplot = "gnuplot");

// DIR/fur.csv, DIR/fur.md, then DIR/fur.png (not without PLOT), each atomic.
void writeFurFiles(const std::vector<FurRow>& rows, const std::filesystem::path& dir,
                   const std::string& title, const std::string& commandLine,
                   const std::string& notes, bool plot = true);

}  // namespace raylab
