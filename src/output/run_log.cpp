#include "output/run_log.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <ostream>
#include <utility>

#include "core/error.hpp"

namespace plisse {
namespace {

/// False when `path` is a non-empty file whose last byte is not '\n'.
bool ends_in_newline(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in || in.tellg() <= 0) return true;
  in.seekg(-1, std::ios::end);
  return in.get() == '\n';
}

}  // namespace

RunLog::RunLog(std::filesystem::path log_file, std::ostream* out, std::ostream* err, LogStart start)
    : log_file_(std::move(log_file)),
      out_(out),
      err_(err),
      start_(std::chrono::steady_clock::now()),
      start_mode_(start) {}

RunLog::RunLog(std::filesystem::path log_file, LogStart start)
    : RunLog(std::move(log_file), &std::cout, &std::cerr, start) {}

RunLog::~RunLog() {
  try {
    flush();
  } catch (const std::exception& e) {
    if (err_ != nullptr) *err_ << "warning: " << e.what() << '\n';
  }
}

void RunLog::info(std::string_view message) { add("", message, out_); }
void RunLog::warn(std::string_view message) { add("warning: ", message, err_); }
void RunLog::error(std::string_view message) { add("error: ", message, err_); }

double RunLog::elapsed_seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

void RunLog::add(std::string_view prefix, std::string_view message, std::ostream* echo) {
  char stamp[32];
  std::snprintf(stamp, sizeof stamp, "[%7.1fs] ", elapsed_seconds());
  std::lock_guard lock(mutex_);
  std::size_t begin = 0;
  do {
    const std::size_t newline = std::min(message.find('\n', begin), message.size());
    const std::string_view line = message.substr(begin, newline - begin);
    if (echo != nullptr) *echo << prefix << line << '\n';
    text_ += stamp;
    text_ += prefix;
    text_ += line;
    text_ += '\n';
    begin = newline + 1;
  } while (begin < message.size());
  if (echo != nullptr) echo->flush();
}

void RunLog::flush() {
  if (log_file_.empty()) return;
  // Writing under the lock keeps concurrent flushes in order: the newest text lands last.
  std::lock_guard lock(mutex_);
  if (!file_) {
    // A run killed inside a write may have left the earlier log's last line unterminated.
    const bool end_line = start_mode_ == LogStart::append && !ends_in_newline(log_file_);
    file_.emplace(log_file_, start_mode_ == LogStart::replace);
    if (end_line) file_->append("\n");
  }
  file_->append(std::string_view(text_).substr(written_));
  written_ = text_.size();
}

std::vector<std::string> RunLog::lines() const {
  std::lock_guard lock(mutex_);
  std::vector<std::string> result;
  for (std::size_t begin = 0; begin < text_.size();) {
    const std::size_t newline = text_.find('\n', begin);
    result.push_back(text_.substr(begin, newline - begin));
    begin = newline + 1;
  }
  return result;
}

}  // namespace plisse
