"""A loopback LLM server whose every reply is malformed (issue 12 point 13):
answers Ollama's /api/chat with `"done": "yes"`. Prints its port, serves until
killed or 60 s idle."""
import http.server
import json
import sys


class Handler(http.server.BaseHTTPRequestHandler):
    def do_POST(self):
        self.rfile.read(int(self.headers.get("Content-Length", 0)))
        body = json.dumps({"message": {"content": "ALT KL204 FL300"}, "done": "yes"}).encode()
        self.send_response(200)
        self.send_header("Content-Type", "application/json")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *args):
        pass


server = http.server.HTTPServer(("127.0.0.1", 0), Handler)
server.timeout = 60
print(server.server_address[1], flush=True)
while True:
    server.handle_request()
