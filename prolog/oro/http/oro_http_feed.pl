:- module(oro_http_feed,
          [ oro_feed_stats/1,           % -Stats
            oro_feed_stop/0
          ]).
:- use_module(library(http/http_dispatch)).
:- use_module(library(http/http_parameters)).
:- use_module(library(http/websocket)).
:- use_module(library(semweb/rdf_db), [rdf_monitor/2]).
:- use_module(library(error)).
:- use_module(library(lists)).
:- use_module(library(apply)).
:- use_module(library(settings)).
:- use_module(library(debug)).
:- use_module(library(oro/oro_store), [oro_graph_layer/3]).
:- use_module(library(oro/oro_names), [oro_iri_name/2]).

/** <module> The live feed of the web inspector

`/api/feed` is a websocket (`?model=M` keeps the changes and events of
model M only) on which the server sends, as JSON text frames, batches
of what happens in the store:

    {"changes": [{"op": "add"|"remove", "model": M, "profile": P,
                  "s": S, "p": P, "o": O}, ...],
     "events":  [{"model": M, "watcher": Id, "content": Text}, ...],
     "commits": [Text, ...],
     "dropped": N}

`changes` are the statements asserted in or removed from the models'
graphs (and the ontology's, with model `null`); `events` the firings of
watchers (oro_events); `commits` what made each change (the transaction
id, `add(Model, Client)` ...).  `dropped` counts what was lost since the
previous batch, because the feed fell behind.

The rdf_monitor/2 callback and the watcher hook only enqueue, without
ever waiting: into one bounded queue (`queue_size`), read by the hub
thread `oro_inspector_feed`, which batches (at most `batch_size` items
or `batch_ms` milliseconds) and hands each batch to the queue of every
client (`client_batches` batches at most: a client that falls behind
loses batches, counted in its next `dropped`).  The callback is
registered while a client is connected only.  The hub gathers and
delivers each batch holding the mutex `oro_inspector_feed_hub`: whoever
holds it holds the feed back (the tests do, to see it drop).
*/

:- setting(queue_size, positive_integer, 20000,
           'Changes waiting for the feed at most; more are dropped').
:- setting(batch_size, positive_integer, 2000,
           'Changes and events per feed message at most').
:- setting(batch_ms, positive_integer, 100,
           'Milliseconds a feed batch gathers changes at most').
:- setting(client_batches, positive_integer, 50,
           'Batches waiting for one feed client at most').

:- http_handler(root(api/feed), feed, [spawn([])]).

%!  oro_feed_stats(-Stats) is det.
%
%   Stats is a dict: `clients` (connected now), `queued` (items waiting
%   for the hub) and `dropped` (items dropped by the callback because
%   the queue was full, since the hub started).

oro_feed_stats(_{clients:Clients, queued:Queued, dropped:Dropped}) :-
    (   catch(message_queue_property(oro_inspector_feed, size(Queued)), _,
              fail)
    ->  true
    ;   Queued = 0
    ),
    flag(oro_inspector_feed_dropped, Dropped, Dropped),
    (   hub_running
    ->  call_hub(clients, Clients)
    ;   Clients = 0
    ).

%!  oro_feed_stop is det.
%
%   Stop the hub thread, if it runs: the callback is unregistered and
%   the feed's queue removed; connected clients get no more batches.
%   The next client starts the hub again, with the settings of then.

oro_feed_stop :-
    with_mutex(oro_inspector_feed,
               (   hub_running
               ->  thread_send_message(oro_inspector_feed, hub(stop, _)),
                   thread_join(oro_inspector_feed_hub, _),
                   message_queue_destroy(oro_inspector_feed)
               ;   true
               )).

		 /*******************************
		 *            CLIENTS           *
		 *******************************/

feed(Request) :-
    http_parameters(Request, [model(Model, [atom, optional(true)])]),
    http_upgrade_to_websocket(client(Model), [], Request).

%   client(+Filter, +WebSocket): this thread reads the websocket (till
%   the browser closes it); a sender thread writes the batches the hub
%   queues for it.

client(Filter, WebSocket) :-
    setting(client_batches, Max),
    message_queue_create(Queue, [max_size(Max)]),
    thread_create(sender(WebSocket, Queue), Sender, []),
    setup_call_cleanup(
        call_hub(join(Queue, Filter), _),
        catch(reader(WebSocket), E,
              debug(oro(http), 'Feed client gone: ~q', [E])),
        ( leave(Queue),
          ignore(thread_send_message(Queue, close, [timeout(5)])),
          thread_join(Sender, _),
          message_queue_destroy(Queue),
          catch(ws_close(WebSocket, 1000, ""), _, true)
        )).

reader(WebSocket) :-
    catch(ws_receive(WebSocket, Message), error(timeout_error(_, _), _),
          Message = timeout),
    (   Message == timeout
    ->  reader(WebSocket)
    ;   memberchk(Message.opcode, [close, end_of_file])
    ->  true
    ;   reader(WebSocket)
    ).

sender(WebSocket, Queue) :-
    thread_get_message(Queue, Batch),
    (   Batch == close
    ->  true
    ;   catch(ws_send(WebSocket, json(Batch)), E,
              ( debug(oro(http), 'Feed client gone: ~q', [E]),
                fail
              ))
    ->  sender(WebSocket, Queue)
    ;   drain_until_close(Queue)
    ).

drain_until_close(Queue) :-
    thread_get_message(Queue, Batch),
    (   Batch == close
    ->  true
    ;   drain_until_close(Queue)
    ).

leave(Queue) :-
    (   hub_running
    ->  call_hub(leave(Queue), _)
    ;   true
    ).

		 /*******************************
		 *          CALLBACKS           *
		 *******************************/

%   monitor(+Event): the rdf_monitor/2 callback: enqueue, never wait.

monitor(transaction(begin(_), _)) :-
    !.
monitor(transaction(end(Nesting), _)) :-
    Nesting > 0,
    !.
monitor(Event) :-
    (   thread_send_message(oro_inspector_feed, Event, [timeout(0)])
    ->  true
    ;   flag(oro_inspector_feed_dropped, N, N+1)
    ).

:- multifile oro_events:fired/3.

oro_events:fired(Model, Id, Content) :-
    feed_listening,
    monitor(fired(Model, Id, Content)).

feed_listening :-
    flag(oro_inspector_feed_clients, N, N),
    N > 0.

		 /*******************************
		 *              HUB             *
		 *******************************/

%   call_hub(+Request, -Reply): ask the hub thread (started on first
%   use) to join or leave a client, or for its number of clients.

call_hub(Request, Reply) :-
    with_mutex(oro_inspector_feed, ensure_hub),
    thread_self(Me),
    thread_send_message(oro_inspector_feed, hub(Request, Me)),
    thread_get_message(Me, hub_reply(Request, Reply0), [timeout(10)]),
    Reply = Reply0.

ensure_hub :-
    (   hub_running
    ->  true
    ;   catch(thread_join(oro_inspector_feed_hub, _), _, true),
        catch(message_queue_destroy(oro_inspector_feed), _, true),
        setting(queue_size, Size),
        message_queue_create(_, [alias(oro_inspector_feed), max_size(Size)]),
        flag(oro_inspector_feed_clients, _, 0),
        thread_create(hub_loop([]), _, [alias(oro_inspector_feed_hub)])
    ).

hub_running :-
    catch(thread_property(oro_inspector_feed_hub, status(running)), _, fail).

%   hub_loop(+Clients): Clients are client(Queue, Filter, Dropped).

hub_loop(Clients) :-
    thread_get_message(oro_inspector_feed, First),
    with_mutex(oro_inspector_feed_hub, hub_batch(First, Clients, Clients1)),
    (   Clients1 == stop
    ->  true
    ;   hub_loop(Clients1)
    ).

%   hub_batch(+First, +Clients0, -Clients): gather a batch from First
%   on, and deliver it.  Clients is `stop` to end the hub.

hub_batch(First, Clients, Next) :-
    get_time(T0),
    setting(batch_ms, Ms),
    Deadline is T0 + Ms/1000,
    setting(batch_size, Max),
    gather(First, Deadline, Max, Items, Requests),
    (   selectchk(stop-_, Requests, Requests1)
    ->  Stop = true
    ;   Stop = false,
        Requests1 = Requests
    ),
    foldl(hub_request, Requests1, Clients, Clients1),
    flag(oro_inspector_feed_dropped, Lost, 0),
    (   Items == [], Lost =:= 0
    ->  Clients2 = Clients1
    ;   maplist(item_json, Items, Jsons),
        maplist(deliver(Jsons, Lost), Clients1, Clients2)
    ),
    (   Stop == false
    ->  Next = Clients2
    ;   Next = stop,
        forall(member(client(Queue, _, _), Clients2),
               ignore(thread_send_message(Queue, close, [timeout(0)]))),
        (   Clients2 == []
        ->  true
        ;   rdf_monitor(oro_http_feed:monitor, [-all])
        )
    ).

%   gather(+First, +Deadline, +Max, -Items, -Requests): the items of one
%   batch, and the hub requests met on the way.

gather(First, Deadline, Max, Items, Requests) :-
    (   First = hub(Request, From)
    ->  Requests = [Request-From|Requests1],
        Items = Items1
    ;   Items = [First|Items1],
        Requests = Requests1
    ),
    (   First = hub(_, _)
    ->  Items1 = [], Requests1 = []
    ;   Max =< 1
    ->  Items1 = [], Requests1 = []
    ;   get_time(Now),
        Wait is max(0, Deadline - Now),
        thread_get_message(oro_inspector_feed, Next, [timeout(Wait)])
    ->  Max1 is Max - 1,
        gather(Next, Deadline, Max1, Items1, Requests1)
    ;   Items1 = [], Requests1 = []
    ).

hub_request(Request-From, Clients0, Clients) :-
    hub_request(Request, Clients0, Clients, Reply),
    thread_send_message(From, hub_reply(Request, Reply)).

hub_request(join(Queue, Filter), Clients, [client(Queue, Filter, 0)|Clients],
            true) :-
    (   Clients == []
    ->  rdf_monitor(oro_http_feed:monitor,
                    [+assert, +retract, +update, +transaction])
    ;   true
    ),
    flag(oro_inspector_feed_clients, N, N+1).
hub_request(leave(Queue), Clients0, Clients, true) :-
    exclude(client_queue(Queue), Clients0, Clients),
    flag(oro_inspector_feed_clients, N, max(0, N-1)),
    (   Clients == []
    ->  rdf_monitor(oro_http_feed:monitor, [-all])
    ;   true
    ).
hub_request(clients, Clients, Clients, N) :-
    length(Clients, N).

client_queue(Queue, client(Queue, _, _)).

%   deliver(+Jsons, +Lost, +Client0, -Client): send Client the items
%   of its model; a full queue drops the batch, counted in the next.

deliver(Jsons, Lost, client(Queue, Filter, Dropped0),
        client(Queue, Filter, Dropped)) :-
    include(for_model(Filter), Jsons, Mine),
    partition(is_kind(change), Mine, Changes, Rest),
    partition(is_kind(event), Rest, Events, Commits0),
    Total is Dropped0 + Lost,
    (   Mine == [], Total =:= 0
    ->  Dropped = 0
    ;   maplist(strip_kind, Changes, ChangesJ),
        maplist(strip_kind, Events, EventsJ),
        maplist(strip_kind, Commits0, CommitsJ),
        Batch = _{changes:ChangesJ, events:EventsJ, commits:CommitsJ,
                  dropped:Total},
        (   thread_send_message(Queue, Batch, [timeout(0)])
        ->  Dropped = 0
        ;   length(Mine, N),
            Dropped is Total + N
        )
    ).

for_model(Filter, Kind-Json) :-
    (   var(Filter)
    ->  true
    ;   Kind == commit
    ->  true
    ;   Json.model == Filter
    ).

is_kind(Kind, Kind-_).

strip_kind(_-Json, Json).

%   item_json(+Item, -Kind-Json): the JSON of a monitored item.

item_json(assert(S, P, O, G), change-J) :-
    !,
    change_json(add, S, P, O, G, J).
item_json(retract(S, P, O, G), change-J) :-
    !,
    change_json(remove, S, P, O, G, J).
item_json(update(S, P, O, G, Action), change-J) :-
    !,
    update_triple(Action, S, P, O, G, S1, P1, O1, G1),
    change_json(update, S1, P1, O1, G1, J).
item_json(fired(Model, Id, Content), event-_{model:Model, watcher:IdT,
                                             content:Text}) :-
    !,
    format(string(IdT), '~w', [Id]),
    format(string(Text), '~w', [Content]).
item_json(Other, commit-Text) :-
    (   Other = transaction(end(0), Id)
    ->  format(string(Text), '~q', [Id])
    ;   format(string(Text), '~q', [Other])
    ).

update_triple(subject(S1), _, P, O, G, S1, P, O, G).
update_triple(predicate(P1), S, _, O, G, S, P1, O, G).
update_triple(object(O1), S, P, _, G, S, P, O1, G).
update_triple(graph(G1), S, P, O, _, S, P, O, G1).

change_json(Op, S, P, O, G0, _{op:Op, model:Model, profile:Profile,
                               s:SN, p:PN, o:ON}) :-
    (   G0 = G:_
    ->  true
    ;   G = G0
    ),
    (   oro_graph_layer(G, Model, profile(Profile))
    ->  true
    ;   Model = null,
        Profile = G
    ),
    term_text(S, SN),
    term_text(P, PN),
    term_text(O, ON).

term_text(literal(L), Text) :-
    !,
    (   ( L = type(_, V) ; L = lang(_, V) )
    ->  true
    ;   V = L
    ),
    format(string(Text), '"~w"', [V]).
term_text(IRI, Text) :-
    oro_iri_name(IRI, Text).
