:- module(oro_events,
          [ oro_events_start/0,
            oro_events_reset/0,
            oro_register_event/7,       % +Model, +Type, +Trigger, +Var, +Patterns, +Subscriber, -Id
            oro_register_event/8,       % +Model, +Type, +Trigger, +Var, +Patterns, +Subscriber, +Registry, -Id
            oro_clear_events/1,         % +Model
            oro_clear_events/2,         % +Model, +Registry
            oro_clear_event/2,          % +Model, +Id
            oro_watchers/2,             % +Model, -Watchers
            oro_subscriber_create/3,    % :Deliver, -Subscriber, +Options
            oro_subscriber_destroy/1,   % +Subscriber
            oro_subscribe/7,            % +Model, +Type, +Trigger, +Var, +Patterns, :Callback, -Id
            oro_unsubscribe/1,          % +Id
            oro_events_sync/0
          ]).
:- use_module(library(semweb/rdf_db)).
:- use_module(library(error)).
:- use_module(library(apply)).
:- use_module(library(lists)).
:- use_module(library(option)).
:- use_module(library(debug)).
:- use_module(library(uuid)).
:- use_module(library(ordsets)).
:- use_module(oro_names).
:- use_module(oro_store).
:- use_module(oro_reason).
:- use_module(oro_query).
:- use_module(oro_parse).

:- meta_predicate
    oro_subscriber_create(2, -, +),
    oro_subscribe(+, +, +, +, +, 2, -).

/** <module> Events: watchers re-checked after every change

Robots react to the world through events: "tell me when an Artifact is
at the kitchen table".  A *watcher* is a pattern over a model with a
type and a trigger (ORO-SPEC §7):

  - `fact_checking`: the patterns (a conjunction) hold or not;
  - `new_instance`: the values a variable takes over the patterns;
  - `new_class_instance`: the instances of a class;

and triggers `on_true`, `on_true_one_shot`, `on_false`,
`on_false_one_shot`, `on_toggle`.  Identical watchers are shared: a
second registration returns the id of the first and adds a subscriber.

How changes reach watchers, exactly once and in order:

  - An rdf_monitor/2 callback, run by the writing thread when a
    transaction commits, only notes which models and predicates it
    touched (and whether the schema changed); at the end of the
    transaction it takes an rdf_db snapshot and queues one `change`
    message.  It never evaluates anything.
  - One watcher thread takes the changes in commit order and evaluates,
    inside the snapshot of each change, the watchers that change may
    affect: those whose patterns use a predicate it touched, directly
    or through sub-properties, inverses, symmetry, transitivity,
    domains and ranges (all watchers of a model when its schema
    changed).  So every transition is seen, even when changes follow
    each other faster than they are evaluated, and the answer does not
    depend on timing.
  - Registration is queued the same way, with a snapshot taken under
    the store's write lock, so the initial state of a watcher is the
    state right before the next change.
  - Firings go to subscribers.  A subscriber owns a bounded queue and a
    delivery thread that calls its Deliver goal: a slow subscriber
    never blocks writers, the watcher thread or other subscribers.  When
    a subscriber's queue is full it has fallen too far behind: it is
    dropped (its subscriptions are removed and its overflow goal, for a
    socket the closing of the connection, is run), so it never silently
    misses an event and stays subscribed.

The watcher thread owns all watcher state; other threads only send it
messages.
*/

:- dynamic
    watcher/5,                      % Id, Model, Registry, Spec, Triples
    watcher_state/2,                % Id, State
    watcher_dep/3,                  % Model, PredicateOrAny, Id
    subscription/2,                 % Id, Subscriber
    subscriber/3,                   % Subscriber, Queue, Thread
    callback_subscriber/2,          % Id, Subscriber
    pending_direct/3,               % Deliver, Id, Content
    model_schema/2,                 % Model, Key (the watcher thread's)
    touched/2,                      % Model, Predicate  (thread_local use)
    touched_schema/0,
    in_commit/0.

:- thread_local
    touched/2,
    touched_schema/0,
    in_commit/0.

		 /*******************************
		 *            START             *
		 *******************************/

%!  oro_events_start is det.
%
%   Start the watcher thread and the store monitor, if not running.

oro_events_start :-
    with_mutex(oro_events,
               (   catch(thread_property(oro_watcher, status(running)), _, fail)
               ->  true
               ;   message_queue_create(_, [alias(oro_watcher_queue)]),
                   thread_create(watcher_loop, _,
                                 [alias(oro_watcher), detached(false)]),
                   rdf_monitor(oro_events:monitor,
                               [-all, +assert, +retract, +update,
                                +transaction])
               )).

%!  oro_events_reset is det.
%
%   Forget every watcher (reset): their ids become unknown.
%   Subscribers stay, with no subscriptions.

oro_events_reset :-
    call_watcher(reset).

%!  oro_events_sync is det.
%
%   Wait until the watcher thread has processed every change committed
%   before the call (its events are then queued to the subscribers).

oro_events_sync :-
    call_watcher(sync).

call_watcher(Request) :-
    oro_events_start,
    thread_self(Me),
    gensym(oro_reply_, Tag),
    thread_send_message(oro_watcher_queue, call(Request, Me, Tag)),
    thread_get_message(reply(Tag, Result)),
    (   Result = error(E)
    ->  throw(E)
    ;   Result = true
    ).

		 /*******************************
		 *           MONITOR            *
		 *******************************/

%   monitor(+Event): called by rdf_db in the writing thread when a
%   transaction commits.  It must stay cheap and never fail or throw.

:- public monitor/1.

monitor(Event) :-
    catch(monitor_(Event), E, print_message(warning, E)),
    !.
monitor(_).

monitor_(transaction(begin(0), _)) :-
    !,
    (   in_commit
    ->  true
    ;   assertz(in_commit)
    ).
monitor_(transaction(end(0), _)) :-
    !,
    retractall(in_commit),
    flush_changes.
monitor_(transaction(_, _)) :-
    !.
monitor_(assert(_, P, O, G)) :-
    !,
    note(G, P, O).
monitor_(retract(_, P, O, G)) :-
    !,
    note(G, P, O).
monitor_(update(_, P, O, G, _)) :-
    !,
    note(G, P, O).
monitor_(_).

note(Source, P, O) :-
    (   watcher(_, _, _, _, _)
    ->  true
    ;   flag(oro_events_pending, N, N),
        N > 0
    ),                                      % nobody watches: nothing to do
    !,
    source_graph(Source, G),
    graph_model(G, Model),
    (   touched(Model, P)
    ->  true
    ;   assertz(touched(Model, P))
    ),
    (   oro_schema_triple(P, O),
        \+ touched_schema
    ->  assertz(touched_schema)
    ;   true
    ),
    (   in_commit
    ->  true
    ;   flush_changes                       % a write outside a transaction
    ).
note(_, _, _).

source_graph(G:_, G) :- !.
source_graph(G, G).

graph_model(G, Model) :-
    (   oro_graph_layer(G, Model0, _)
    ->  Model = Model0
    ;   oro_ontology_graph(G)
    ->  Model = '$all'
    ;   Model = '$none'
    ).

flush_changes :-
    findall(M-P, retract(touched(M, P)), Touched),
    (   retract(touched_schema)
    ->  Schema = true
    ;   Schema = false
    ),
    (   Touched == []
    ->  true
    ;   (   Schema == true
        ;   pending
        ;   relevant(Touched)
        )
    ->  (   Schema == true
        ->  flag(oro_events_pending, N, N+1)
        ;   true
        ),
        rdf_snapshot(Snapshot),
        thread_send_message(oro_watcher_queue,
                            change(Snapshot, Touched, Schema))
    ;   true
    ).

%   A change that no watcher depends on is not sent at all.  The
%   dependencies are those of the watchers the watcher thread knows, so
%   while it has not yet processed a registration or a schema change
%   (which may change dependencies) every change is sent: the counter
%   oro_events_pending is raised, under the store's write lock, when one
%   is queued and lowered by the watcher thread once it is done.

pending :-
    flag(oro_events_pending, N, N),
    N > 0.

relevant(Touched) :-
    member(Model-P, Touched),
    (   Model == '$all'
    ;   watcher_dep(Model, any, _)
    ;   watcher_dep(Model, P, _)
    ),
    !.

		 /*******************************
		 *         REGISTRATION         *
		 *******************************/

%!  oro_register_event(+Model, +Type, +Trigger, +Var, +Patterns,
%!                     +Subscriber, -Id) is det.
%
%   Register a watcher on Model and subscribe Subscriber to it.  Type
%   and Trigger are names as ORO spells them, in any case
%   (`NEW_INSTANCE`, `on_true`); Var is the variable of a
%   `new_instance` watcher (`o` or `?o`, ignored by the other types);
%   Patterns are statement texts or rdf/3 terms (a `new_class_instance`
%   watcher takes one class name).  Id is the id of the watcher (a
%   UUID atom): that of an identical watcher if one exists.  The
%   registry of the watcher is the Subscriber's `registry` (see
%   oro_subscriber_create/3).
%
%   @error domain_error(oro_event_type, Type)
%   @error domain_error(oro_event_trigger, Trigger)
%   @error domain_error(oro_event_variable, Var) for a `new_instance`
%          watcher without a variable.
%   @error oro_event_registration(Message) for a bad pattern.

oro_register_event(Model, Type, Trigger, Var, Patterns, Subscriber, Id) :-
    subscriber_registry(Subscriber, Registry),
    oro_register_event(Model, Type, Trigger, Var, Patterns, Subscriber,
                       Registry, Id).

%!  oro_register_event(+Model, +Type, +Trigger, +Var, +Patterns,
%!                     +Subscriber, +Registry, -Id) is det.
%
%   As oro_register_event/7, the watcher going to Registry (`plain`,
%   `agent` or `internal`) whatever the subscriber's default: one
%   subscriber (one connection) may register in several registries and
%   still receives all its events in commit order.

oro_register_event(Model0, Type0, Trigger0, Var0, Patterns, Subscriber,
                   Registry, Id) :-
    oro_resolve_model(Model0, Model),
    event_type(Type0, Type),
    event_trigger(Trigger0, Trigger),
    must_be(list, Patterns),
    must_be(oneof([plain, agent, internal]), Registry),
    event_var(Type, Var0, Var),
    subscriber_registry(Subscriber, _),
    watcher_triples(Type, Model, Var, Patterns, Triples),
    Spec = spec(Type, Trigger, Var, Patterns),
    oro_events_start,
    thread_self(Me),
    gensym(oro_reply_, Tag),
    with_mutex(oro_write,
               ( rdf_snapshot(Snapshot),
                 flag(oro_events_pending, N, N+1),
                 thread_send_message(oro_watcher_queue,
                                     call(register(Model, Registry, Spec, Triples,
                                                   Subscriber, Snapshot),
                                          Me, Tag))
               )),
    thread_get_message(reply(Tag, Result)),
    (   Result = error(E)
    ->  throw(E)
    ;   Result = id(Id)
    ).

event_type(Text, Type) :-
    must_be(text, Text),
    atom_string(Atom, Text),
    downcase_atom(Atom, Type),
    (   memberchk(Type, [fact_checking, new_instance, new_class_instance])
    ->  true
    ;   domain_error(oro_event_type, Text)
    ).

event_trigger(Text, Trigger) :-
    must_be(text, Text),
    atom_string(Atom, Text),
    downcase_atom(Atom, Trigger),
    (   memberchk(Trigger, [on_true, on_true_one_shot, on_false,
                            on_false_one_shot, on_toggle])
    ->  true
    ;   domain_error(oro_event_trigger, Text)
    ).

event_var(new_instance, Var0, Var) :-
    !,
    (   text(Var0),
        atom_string(A, Var0),
        normalize_space(atom(A1), A),
        (   sub_atom(A1, 0, 1, _, ?)
        ->  sub_atom(A1, 1, _, 0, Var)
        ;   Var = A1
        ),
        Var \== ''
    ->  true
    ;   domain_error(oro_event_variable, Var0)
    ).
event_var(_, _, '').

text(X) :- string(X), !.
text(X) :- atom(X).

%   The patterns of a watcher as triples with the variables of the
%   new_instance variable shared; a new_class_instance watcher watches
%   `?instance rdf:type Class`.

watcher_triples(new_class_instance, Model, _, Patterns, [rdf(_, Type, Class)]) :-
    !,
    (   Patterns = [Name]
    ->  true
    ;   length(Patterns, N),
        throw(error(oro_event_registration(class_pattern(N)), _))
    ),
    oro_name_class(Name, Class),
    rdf_equal(rdf:type, Type),
    (   oro_class(Model, Class)
    ->  true
    ;   throw(error(oro_event_registration(unknown_class(Name)), _))
    ).
watcher_triples(_, _, _, Patterns, Triples) :-
    catch(oro_statements(Patterns, Triples, _), error(Formal, _),
          throw(error(oro_event_registration(pattern(Formal)), _))).

oro_name_class(Name, Class) :-
    (   text(Name)
    ->  oro_name_iri(Name, Class)
    ;   oro_resource(Name, Class)
    ).

%!  oro_clear_events(+Model) is det.
%
%   Remove every watcher of Model registered without an agent (plain
%   registerEvent): ORO's clearEvents().

oro_clear_events(Model) :-
    oro_clear_events(Model, plain).

%!  oro_clear_events(+Model, +Registry) is det.
%
%   Remove every watcher of Model in Registry: `plain` (registerEvent)
%   or `agent` (registerEventForAgent, ORO's clearEventsForAgent()).

oro_clear_events(Model0, Registry) :-
    oro_resolve_model(Model0, Model),
    must_be(oneof([plain, agent, internal]), Registry),
    call_watcher(clear(Model, Registry)).

%!  oro_clear_event(+Model, +Id) is det.
%
%   Remove the watcher Id of Model.
%   @error existence_error(event, Id) if there is none.
%   @error domain_error(uuid, Id) if Id is not a UUID.

oro_clear_event(Model0, Id0) :-
    oro_resolve_model(Model0, Model),
    must_be(text, Id0),
    atom_string(Id, Id0),
    (   catch(uuid_property(Id, version(_)), _, fail)
    ->  true
    ;   domain_error(uuid, Id0)
    ),
    call_watcher(clear_one(Model, Id)).

%!  oro_watchers(+Model, -Watchers) is det.
%
%   Watchers of Model, as watcher(Id, Type, Trigger, Var, Patterns,
%   Subscribers) terms, Subscribers being their number; oro's own
%   (`internal`) watchers are not listed.

oro_watchers(Model0, Watchers) :-
    oro_resolve_model(Model0, Model),
    findall(watcher(Id, Type, Trigger, Var, Patterns, N),
            ( watcher(Id, Model, Registry, spec(Type, Trigger, Var, Patterns), _),
              Registry \== internal,
              aggregate_all(count, subscription(Id, _), N)
            ),
            Watchers).

		 /*******************************
		 *          SUBSCRIBERS         *
		 *******************************/

:- predicate_options(oro_subscriber_create/3, 3,
                     [ max_queue(positive_integer),
                       on_overflow(callable),
                       registry(oneof([plain, agent, internal])),
                       in_watcher(boolean)
                     ]).

%!  oro_subscriber_create(:Deliver, -Subscriber, +Options) is det.
%
%   Create a subscriber: a bounded queue and a thread calling
%   call(Deliver, Id, Content) for each firing of the watchers it
%   subscribes to, in order.  Content is [] for `fact_checking`
%   watchers, else the list of new (or removed) values.  Options:
%
%     - max_queue(+N): firings waiting at most (default 10000); past it
%       the subscriber is dropped;
%     - on_overflow(:Goal): called (in a thread of its own) when it is
%       dropped;
%     - registry(+Registry): `plain` (default) or `agent`, which
%       clearEvents() and clearEventsForAgent() address apart, or
%       `internal`, which neither clears (oro's own watchers);
%     - in_watcher(+Bool): if `true`, Deliver is called directly by the
%       watcher thread, before the change is considered processed (see
%       oro_events_sync/0).  For oro's own short, non-blocking
%       reactions only, such as creating agent models.

oro_subscriber_create(Deliver, Subscriber, Options) :-
    must_be(list, Options),
    option(max_queue(Max), Options, 10000),
    option(on_overflow(OnOverflow), Options, true),
    option(registry(Registry), Options, plain),
    option(in_watcher(InWatcher), Options, false),
    gensym(oro_subscriber_, Name),
    Subscriber = subscriber(Name, Registry, OnOverflow),
    (   InWatcher == true
    ->  Queue = direct(Deliver),
        Thread = none
    ;   message_queue_create(Queue, [max_size(Max)]),
        thread_create(deliver_loop(Queue, Deliver), Thread, [])
    ),
    with_mutex(oro_events, assertz(subscriber(Subscriber, Queue, Thread))).

subscriber_registry(subscriber(_, Registry, _), Registry) :-
    !.
subscriber_registry(Subscriber, _) :-
    type_error(oro_subscriber, Subscriber).

%!  oro_subscriber_destroy(+Subscriber) is det.
%
%   Unsubscribe Subscriber from every watcher (watchers left without
%   subscribers are dropped), deliver what it has queued and stop its
%   thread.

oro_subscriber_destroy(Subscriber) :-
    (   subscriber(Subscriber, direct(_), _)
    ->  call_watcher(unsubscribe(Subscriber)),
        with_mutex(oro_events, retractall(subscriber(Subscriber, _, _)))
    ;   subscriber(Subscriber, Queue, Thread)
    ->  call_watcher(unsubscribe(Subscriber)),
        thread_send_message(Queue, '$stop'),
        thread_self(Me),
        (   Thread == Me
        ->  true
        ;   thread_join(Thread, _)
        ),
        with_mutex(oro_events, retractall(subscriber(Subscriber, _, _))),
        message_queue_destroy(Queue)
    ;   true
    ).

deliver_loop(Queue, Deliver) :-
    thread_get_message(Queue, Message),
    (   Message == '$stop'
    ->  true
    ;   Message = event(Id, Content),
        catch(call(Deliver, Id, Content), E,
              print_message(warning, E)),
        deliver_loop(Queue, Deliver)
    ).

%!  oro_subscribe(+Model, +Type, +Trigger, +Var, +Patterns, :Callback,
%!                -Id) is det.
%
%   Register a watcher (see oro_register_event/7) whose firings call
%   call(Callback, Id, Content) in a thread of its own: the Prolog
%   equivalent of registerEvent for a planner in the same process.

oro_subscribe(Model, Type, Trigger, Var, Patterns, Callback, Id) :-
    oro_subscriber_create(Callback, Subscriber, []),
    catch(oro_register_event(Model, Type, Trigger, Var, Patterns,
                             Subscriber, Id),
          E,
          ( oro_subscriber_destroy(Subscriber),
            throw(E)
          )),
    with_mutex(oro_events, assertz(callback_subscriber(Id, Subscriber))).

%!  oro_unsubscribe(+Id) is det.
%
%   Stop the callbacks set by oro_subscribe/7 for watcher Id.

oro_unsubscribe(Id) :-
    must_be(atom, Id),
    with_mutex(oro_events,
               findall(S, retract(callback_subscriber(Id, S)), Subscribers)),
    maplist(oro_subscriber_destroy, Subscribers).

		 /*******************************
		 *        WATCHER THREAD        *
		 *******************************/

watcher_loop :-
    thread_get_message(oro_watcher_queue, Message),
    catch(handle(Message), E, print_message(error, E)),
    watcher_loop.

handle(change(Snapshot, Touched, Schema)) :-
    call_cleanup(process_change(Snapshot, Touched, Schema),
                 ( rdf_delete_snapshot(Snapshot),
                   (   Schema == true
                   ->  flag(oro_events_pending, N, N-1)
                   ;   true
                   )
                 )),
    run_direct_deliveries.
handle(call(Request, Thread, Tag)) :-
    (   catch(request(Request, Result0), E, (Result0 = error(E)))
    ->  Result = Result0
    ;   Result = error(failed(Request))
    ),
    thread_send_message(Thread, reply(Tag, Result)).

%   Deliveries to in_watcher subscribers run once the snapshot
%   transaction is over, so they may change the store.

run_direct_deliveries :-
    forall(retract(pending_direct(Deliver, Id, Content)),
           catch(call(Deliver, Id, Content), E,
                 print_message(warning, E))).

request(sync, true).
request(reset, true) :-
    retractall(watcher(_, _, _, _, _)),
    retractall(watcher_state(_, _)),
    retractall(watcher_dep(_, _, _)),
    retractall(subscription(_, _)),
    forall(retract(model_schema(_, Key)), oro_drop_schema(Key)).
request(register(Model, Registry, Spec, Triples, Subscriber, Snapshot), id(Id)) :-
    call_cleanup(register(Model, Registry, Spec, Triples, Subscriber,
                          Snapshot, Id),
                 ( rdf_delete_snapshot(Snapshot),
                   flag(oro_events_pending, N, N-1)
                 )).
request(clear(Model, Registry), true) :-
    forall(watcher(Id, Model, Registry, _, _), drop_watcher(Id)).
request(clear_one(Model, Id), true) :-
    (   watcher(Id, Model, _, _, _)
    ->  drop_watcher(Id)
    ;   existence_error(event, Id)
    ).
request(unsubscribe(Subscriber), true) :-
    forall(retract(subscription(Id, Subscriber)),
           drop_if_orphan(Id)).

register(Model, Registry, Spec, _, Subscriber, _, Id) :-
    watcher(Id, Model, Registry, Spec, _),
    !,
    (   subscription(Id, Subscriber)
    ->  true
    ;   assertz(subscription(Id, Subscriber))
    ).
register(Model, Registry, Spec, Triples, Subscriber, Snapshot, Id) :-
    uuid(Id, [version(4)]),
    rdf_transaction(ensure_schemas([Model]), oro(events), [snapshot(Snapshot)]),
    in_snapshot(Snapshot, [Model],
                ( initial_state(Spec, Model, Triples, State),
                  watcher_deps(Spec, Model, Triples, State, Deps)
                )),
    assertz(watcher(Id, Model, Registry, Spec, Triples)),
    assertz(watcher_state(Id, State)),
    forall(member(D, Deps), assertz(watcher_dep(Model, D, Id))),
    assertz(subscription(Id, Subscriber)),
    debug(oro(events), 'Watcher ~w: ~q', [Id, Spec]).

%   The initial state: fact_checking watchers start `false` and are not
%   evaluated (ORO-SPEC §7.3); the others remember their current values.

initial_state(spec(fact_checking, _, _, _), _, _, unknown) :- !.
initial_state(Spec, Model, Triples, values(Values)) :-
    evaluate(Spec, Model, Triples, values(Values)).

%   A fact_checking watcher not evaluated yet depends on any change (it
%   fires at the first one if already true); so do one-shot triggers
%   without edge detection, which fire at any change (ORO-SPEC §7.3).

watcher_deps(spec(fact_checking, Trigger, _, _), _, _, State, [any]) :-
    (   State == unknown
    ;   memberchk(Trigger, [on_true_one_shot, on_false_one_shot])
    ),
    !.
watcher_deps(_, Model, Triples, _, Deps) :-
    oro_pattern_dependencies(Model, Triples, Deps).

drop_watcher(Id) :-
    retractall(watcher(Id, _, _, _, _)),
    retractall(watcher_state(Id, _)),
    retractall(watcher_dep(_, _, Id)),
    retractall(subscription(Id, _)).

drop_if_orphan(Id) :-
    (   subscription(Id, _)
    ->  true
    ;   drop_watcher(Id)
    ).

%   in_snapshot(+Snapshot, +Models, :Goal): run Goal in the snapshot,
%   with the schemas the watcher thread compiled for Models.

in_snapshot(Snapshot, Models, Goal) :-
    rdf_transaction(with_schemas(Models, Goal), oro(events), [snapshot(Snapshot)]).

with_schemas(Models, Goal) :-
    findall(M-K, ( member(M, Models), model_schema(M, K) ), Keys),
    oro_with_schemas(Keys, Goal).

		 /*******************************
		 *           CHANGES            *
		 *******************************/

process_change(Snapshot, Touched, Schema) :-
    (   Schema == true
    ->  forget_schemas(Touched)
    ;   true
    ),
    affected_models(Touched, Models),
    (   Models == []
    ->  true
    ;   rdf_transaction(change_in_snapshot(Models, Touched, Schema),
                        oro(events), [snapshot(Snapshot)])
    ).

%   After a schema change, the schemas the watcher thread compiled for
%   the models it touched are stale: they are compiled again, in the
%   snapshot of the next change or registration that needs them.

forget_schemas(Touched) :-
    (   memberchk('$all'-_, Touched)
    ->  forall(retract(model_schema(_, Key)), oro_drop_schema(Key))
    ;   forall(( member(M-_, Touched),
                 retract(model_schema(M, Key))
               ),
               oro_drop_schema(Key))
    ).

affected_models(Touched, Models) :-
    (   memberchk('$all'-_, Touched)
    ->  findall(M, watcher(_, M, _, _, _), Models0)
    ;   findall(M, ( member(M-_, Touched), watcher(_, M, _, _, _) ), Models0)
    ),
    sort(Models0, Models).

change_in_snapshot(Models, Touched, Schema) :-
    ensure_schemas(Models),
    with_schemas(Models, evaluate_models(Models, Touched, Schema)).

ensure_schemas(Models) :-
    forall(( member(M, Models),
             \+ model_schema(M, _)
           ),
           ( oro_compile_schema(M, Key),
             assertz(model_schema(M, Key))
           )).

evaluate_models(Models, Touched, Schema) :-
    forall(member(Model, Models),
           evaluate_model(Model, Touched, Schema)).

evaluate_model(Model, Touched, Schema) :-
    (   Schema == true
    ->  findall(Id, watcher(Id, Model, _, _, _), Ids0)
    ;   findall(Id, ( watcher_dep(Model, any, Id)
                    ; ( member(Model-P, Touched) ; member('$all'-P, Touched) ),
                      watcher_dep(Model, P, Id)
                    ), Ids0)
    ),
    sort(Ids0, Ids1),
    order_by_registration(Ids1, Ids),
    forall(member(Id, Ids), evaluate_watcher(Id, Schema)).

%   Watchers are evaluated in the order they were registered, so that
%   two firings of one change reach a subscriber in a stable order.

order_by_registration(Ids0, Ids) :-
    findall(Id, ( watcher(Id, _, _, _, _), memberchk(Id, Ids0) ), Ids).

evaluate_watcher(Id, Schema) :-
    watcher(Id, Model, _, Spec, Triples),
    watcher_state(Id, State0),
    !,
    evaluate(Spec, Model, Triples, State),
    Spec = spec(Type, Trigger, _, _),
    firings(Type, Trigger, State0, State, Contents, Remove),
    retractall(watcher_state(Id, _)),
    assertz(watcher_state(Id, State)),
    forall(member(Content, Contents), fire(Id, Content)),
    (   Remove == true
    ->  drop_watcher(Id)
    ;   (   Schema == true
        ;   State0 == unknown
        )
    ->  refresh_deps(Id, Model, Spec, Triples, State)
    ;   true
    ).
evaluate_watcher(_, _).                     % dropped meanwhile

%   The new dependencies are added before the old ones go: writers read
%   them (relevant/1) to decide whether to send a change, and must never
%   see a watcher with none.

refresh_deps(Id, Model, Spec, Triples, State) :-
    watcher_deps(Spec, Model, Triples, State, Deps),
    findall(D, watcher_dep(Model, D, Id), Old),
    forall(( member(D, Deps), \+ memberchk(D, Old) ),
           assertz(watcher_dep(Model, D, Id))),
    forall(( member(D, Old), \+ memberchk(D, Deps) ),
           retractall(watcher_dep(Model, D, Id))).

evaluate(spec(fact_checking, _, _, _), Model, Triples, truth(Truth)) :-
    !,
    copy_term(Triples, Copy),
    (   oro_solve(Model, Copy)
    ->  Truth = true
    ;   Truth = false
    ).
evaluate(spec(new_class_instance, _, _, _), Model, [rdf(_, _, Class)], values(Values)) :-
    !,
    rdf_equal(rdf:type, Type),
    oro_find_values(Model, X, [rdf(X, Type, Class)], Values).
evaluate(spec(new_instance, _, Var, Patterns), Model, _, values(Values)) :-
    oro_statements(Patterns, Triples, Bindings),
    (   memberchk(Var=Template, Bindings)
    ->  oro_find_values(Model, Template, Triples, Values)
    ;   Values = []
    ).

%!  firings(+Type, +Trigger, +State0, +State, -Contents, -Remove)
%
%   The events a watcher sends when its state goes from State0 to
%   State (ORO-SPEC §7.3), and whether it is then removed.

firings(fact_checking, Trigger, State0, truth(R), Contents, Remove) :-
    (   State0 == truth(true)
    ->  Last = true
    ;   Last = false
    ),
    fact_firing(Trigger, Last, R, Fire, Remove),
    (   Fire == true
    ->  Contents = [[]]
    ;   Contents = []
    ).
firings(new_instance, Trigger, values(Before), values(Now), Contents, Remove) :-
    ord_subtract(Now, Before, Added),
    ord_subtract(Before, Now, Removed),
    instance_firing(Trigger, Added, Removed, Contents, Remove).
firings(new_class_instance, Trigger, values(Before), values(Now), Contents, Remove) :-
    ord_subtract(Now, Before, Added),
    (   Added \== [],
        memberchk(Trigger, [on_true, on_true_one_shot])
    ->  Contents = [Added],
        (   Trigger == on_true_one_shot
        ->  Remove = true
        ;   Remove = false
        )
    ;   Contents = [],
        Remove = false
    ).

fact_firing(on_true, Last, R, Fire, false) :-
    (   R == true, Last == false -> Fire = true ; Fire = false ).
fact_firing(on_false, Last, R, Fire, false) :-
    (   R == false, Last == true -> Fire = true ; Fire = false ).
fact_firing(on_toggle, Last, R, Fire, false) :-
    (   R \== Last -> Fire = true ; Fire = false ).
fact_firing(on_true_one_shot, _, R, Fire, Fire) :-
    (   R == true -> Fire = true ; Fire = false ).
fact_firing(on_false_one_shot, _, R, Fire, Fire) :-
    (   R == false -> Fire = true ; Fire = false ).

instance_firing(on_true, Added, _, Contents, false) :-
    non_empty(Added, Contents).
instance_firing(on_false, _, Removed, Contents, false) :-
    non_empty(Removed, Contents).
instance_firing(on_toggle, Added, Removed, Contents, false) :-
    non_empty(Removed, C1),
    non_empty(Added, C2),
    append(C1, C2, Contents).
instance_firing(on_true_one_shot, Added, _, Contents, Remove) :-
    non_empty(Added, Contents),
    one_shot(Contents, Remove).
instance_firing(on_false_one_shot, _, Removed, Contents, Remove) :-
    non_empty(Removed, Contents),
    one_shot(Contents, Remove).

non_empty([], []) :- !.
non_empty(Values, [Values]).

one_shot([], false) :- !.
one_shot(_, true).

%   fire(+Id, +Content): queue the firing to every subscriber, without
%   ever waiting.  A full queue drops its subscriber.

fire(Id, Content) :-
    forall(subscription(Id, Subscriber),
           send_firing(Subscriber, Id, Content)).

send_firing(Subscriber, Id, Content) :-
    (   subscriber(Subscriber, direct(Deliver), _)
    ->  assertz(pending_direct(Deliver, Id, Content))  % run after the snapshot
    ;   subscriber(Subscriber, Queue, _),
        thread_send_message(Queue, event(Id, Content), [timeout(0)])
    ->  true
    ;   overflow(Subscriber)
    ).

overflow(Subscriber) :-
    print_message(warning, format("oro: event subscriber ~w fell behind: \c
                                   dropped", [Subscriber])),
    forall(retract(subscription(Id, Subscriber)), drop_if_orphan(Id)),
    Subscriber = subscriber(_, _, OnOverflow),
    thread_create(ignore(catch(OnOverflow, _, true)), _, [detached(true)]).
