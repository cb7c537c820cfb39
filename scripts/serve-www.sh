# Sourced by the page's test steps: serves www/ on a free local port in the background, stops it on
# exit, and waits until it answers. Sets `port`.
port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server "$port" --bind 127.0.0.1 --directory www >/dev/null 2>&1 &
server=$!
trap 'kill "$server" 2>/dev/null || true' EXIT
# Wait for the server (it answers within about 0.1 s; 30 s is only a hang guard).
start=$SECONDS
until python3 -c "import urllib.request; urllib.request.urlopen('http://127.0.0.1:$port/')" 2>/dev/null; do
  (( SECONDS - start < 30 )) || { echo "the local web server did not answer within 30 s" >&2; exit 1; }
  sleep 0.1
done
