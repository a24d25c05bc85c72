#include "coordinator/web/api_router.h"

#include <iostream>
#include <nlohmann/json.hpp>

#include "common/process/wall_clock.h"
#include "common/store/results_reader.h"
#include "common/store/sqlite_db.h"
#include "common/store/store_db.h"
#include "common/store/store_error.h"
#include "coordinator/web/access_control.h"
#include "coordinator/web/api_error.h"
#include "coordinator/web/artifact_file.h"
#include "coordinator/web/campaign_views.h"
#include "coordinator/web/map_views.h"
#include "coordinator/web/page_assets.h"
#include "coordinator/web/plot_views.h"

namespace rlpos::web {
namespace {

using nlohmann::json;

// The database as the page reads it: opened read-only by SQLite, and query_only besides, so no
// statement of any request can write.
struct ReadOnlyStore {
  static StoreOptions Options() {
    StoreOptions options;
    options.read_only = true;
    options.busy_timeout_ms = 2000;
    return options;
  }
  explicit ReadOnlyStore(const std::string& file) : db(file, Options()), reader(db) {
    db.sql().Exec("PRAGMA query_only = ON");
  }
  StoreDb db;
  ResultsReader reader;
};

ApiResponse JsonResponse(const json& body) {
  ApiResponse response;
  // Invalid UTF-8 from the database (an error text) is replaced, never a failed answer.
  response.body = body.dump(-1, ' ', false, json::error_handler_t::replace);
  return response;
}

void RequireAccess(const HttpRequestView& request, const ServeContext& context) {
  if (!context.token) {
    if (!IsLoopbackHostHeader(request.host))
      throw ApiError(403, "the Host header must name the loopback (127.0.0.1 or localhost)");
    return;
  }
  if (const auto bearer = BearerToken(request.authorization)) {
    if (SameToken(*bearer, *context.token))
      return;
    throw ApiError(401, "wrong token");
  }
  // The page's first load comes from a link: its token may ride in the query, once.
  if (request.path == "/" || request.path == "/index.html") {
    for (const auto& [name, value] : request.query) {
      if (name == "token" && SameToken(value, *context.token))
        return;
    }
  }
  throw ApiError(401, "a token is needed: Authorization: Bearer <token>");
}

void RequireCampaign(ResultsReader& store, const std::string& campaign_id) {
  if (!store.CampaignSpecPart(campaign_id, "name"))
    throw ApiError(404, "no campaign " + campaign_id);
}

ApiResponse Answer(const ApiRequest& request, const ServeContext& context) {
  ReadOnlyStore store(context.db_file);
  ResultsReader& reader = store.reader;
  const double now = context.clock ? context.clock() : WallClockSeconds();
  switch (request.endpoint) {
    case Endpoint::kCampaigns:
      return JsonResponse(CampaignListJson(reader, now));
    case Endpoint::kArtifact: {
      const ServedArtifact artifact = ResolveArtifact(reader, request.artifact_id);
      ApiResponse response;
      response.content_type = "application/octet-stream";
      response.file = artifact.file;
      response.download_name = artifact.name;
      return response;
    }
    default:
      break;
  }
  RequireCampaign(reader, request.campaign_id);
  switch (request.endpoint) {
    case Endpoint::kCampaign: {
      json detail = CampaignDetailJson(reader, request.campaign_id, now);
      detail["metrics"] = DistributionMetricsJson();
      return JsonResponse(detail);
    }
    case Endpoint::kDistributions:
      return JsonResponse(DistributionJson(reader, request.campaign_id, request.metric,
                                           request.kind, request.scenario));
    case Endpoint::kLearningCurves:
      return JsonResponse(LearningCurvesJson(reader, request.campaign_id, request.scenario));
    case Endpoint::kMaps:
      return JsonResponse(ScenarioMapsJson(reader, request.campaign_id).value_or(json::object()));
    default:
      throw ApiError(404, "no such endpoint");
  }
}

ApiResponse PageResponse() {
  ApiResponse response;
  response.content_type = "text/html; charset=utf-8";
  response.body = PageHtml();
  response.headers.push_back({"Content-Security-Policy", PageContentSecurityPolicy()});
  return response;
}

// One line, printable, bounded: what an error message may carry to the client.
std::string OneLine(const std::string& text) {
  std::string out;
  for (char c : text.substr(0, 300))
    out += (c == '\n' || c == '\r' || c == '\t') ? ' ' : c;
  return out;
}

}  // namespace

ApiResponse ErrorResponse(int status, const std::string& message) {
  ApiResponse response;
  response.status = status;
  response.body =
      json{{"error", OneLine(message)}}.dump(-1, ' ', false, json::error_handler_t::replace) + "\n";
  return response;
}

ApiResponse MethodNotAllowed() {
  ApiResponse response = ErrorResponse(405, "only GET and HEAD are served");
  response.headers.push_back({"Allow", "GET, HEAD"});  // what a 405 must name (RFC 9110)
  return response;
}

ApiResponse Respond(const HttpRequestView& request, const ServeContext& context) {
  try {
    if (request.method != "GET" && request.method != "HEAD")
      return MethodNotAllowed();
    RequireAccess(request, context);
    const ApiRequest parsed = ParseApiRequest(request.path, request.query);
    if (parsed.endpoint == Endpoint::kPage)
      return PageResponse();
    return Answer(parsed, context);
  } catch (const ApiError& e) {
    return ErrorResponse(e.status(), e.what());
  } catch (const StoreError& e) {
    // The message names the server's own file: said on its stderr, not to the client.
    std::cerr << "rlpos-campaign serve: " << OneLine(e.what()) << "\n";
    return ErrorResponse(503, "the results database cannot be read now");
  } catch (const std::exception& e) {
    std::cerr << "rlpos-campaign serve: " << OneLine(e.what()) << "\n";
    return ErrorResponse(500, "internal error");
  }
}

}  // namespace rlpos::web
